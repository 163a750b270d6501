#include "gi/surface_cache/surface_cache_atlas.h"

namespace lumina::surface_cache {

const char* atlasLayerName(AtlasLayer layer) {
    static const char* const names[kAtlasLayerCount] = {"albedo",       "normal",         "material",
                                                        "direct light", "indirect light", "final lighting"};
    return uint32_t(layer) < kAtlasLayerCount ? names[uint32_t(layer)] : "?";
}

SurfaceCacheAtlas::SurfaceCacheAtlas(rhi::IDevice& device, const SurfaceCacheSettings& settings)
    : size_((validate(settings), settings.atlasSize)) {
    const auto create = [&](rhi::TextureDimension dimension, rhi::Format format, uint32_t layers,
                            rhi::TextureUsage usage, const char* name) {
        return device.createTexture({.dimension = dimension,
                                     .format = format,
                                     .width = size_,
                                     .height = size_,
                                     .arrayLayers = layers,
                                     .usage = usage | rhi::TextureUsage::Sampled,
                                     .debugName = name});
    };
    using rhi::Format;
    using rhi::TextureDimension;
    using rhi::TextureUsage;
    albedo = create(TextureDimension::Texture2D, Format::RGBA16_FLOAT, 1, TextureUsage::RenderTarget,
                    "surface cache albedo");
    surface = create(TextureDimension::Texture2DArray, Format::RGBA16_FLOAT, 2, TextureUsage::RenderTarget,
                     "surface cache normal and material");
    direct = create(TextureDimension::Texture2D, Format::RGBA16_FLOAT, 1, TextureUsage::Storage,
                    "surface cache direct light");
    indirect = create(TextureDimension::Texture2D, Format::RGBA16_FLOAT, 1, TextureUsage::Storage,
                      "surface cache indirect light");
    final = create(TextureDimension::Texture2D, Format::RGBA16_FLOAT, 1, TextureUsage::Storage,
                   "surface cache final lighting");
    layers_ = {AtlasLayerView{albedo, 0}, AtlasLayerView{surface, 0},  AtlasLayerView{surface, 1},
               AtlasLayerView{direct, 0}, AtlasLayerView{indirect, 0}, AtlasLayerView{final, 0}};
}

void SurfaceCacheAtlas::recordClear(rhi::ICommandList& commands) const {
    for (const rhi::TextureHandle& texture : {albedo, surface, direct, indirect, final}) {
        commands.clearColor(*texture, {0.0f, 0.0f, 0.0f, 0.0f});
    }
}

uint64_t SurfaceCacheAtlas::bytes() const {
    const uint64_t texels = uint64_t(size_) * size_;
    return texels * 8 + texels * 8 * 2 + texels * 8 * 3;
}

} // namespace lumina::surface_cache
