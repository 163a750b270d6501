#include "gi/screen_probes/surface_cache_view.h"

#include "gi/surface_cache/surface_cache.h"

#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

void checkTexture(const rhi::TextureHandle& texture, const char* what, rhi::TextureDimension dimension,
                  const char* expected) {
    if (!texture) {
        throw std::invalid_argument(std::string("screen probes: surface cache ") + what + " missing");
    }
    const rhi::TextureDesc& desc = texture->desc();
    if (desc.dimension != dimension || desc.format != rhi::Format::RGBA16_FLOAT || desc.arrayLayers != 1) {
        throw std::invalid_argument(std::string("screen probes: surface cache ") + what + " '" +
                                    desc.debugName + "' must be " + expected);
    }
}

} // namespace

SurfaceCacheView surfaceCacheView(const surface_cache::SurfaceCache& cache) {
    return {.finalLighting = cache.atlas().layer(surface_cache::AtlasLayer::FinalLighting).texture,
            .cards = cache.cardBuffer(),
            .cardBvh = cache.cardBvhBuffer(),
            .voxelLighting = cache.voxelLighting().volume(),
            .voxelGrid = cache.voxelLighting().grid()};
}

void checkSurfaceCacheView(const SurfaceCacheView& view) {
    checkTexture(view.finalLighting, "final lighting", rhi::TextureDimension::Texture2D,
                 "an RGBA16F 2D texture (one layer)");
    checkTexture(view.voxelLighting, "voxel lighting", rhi::TextureDimension::Texture3D,
                 "an RGBA16F 3D texture");
    if (!view.cards || !view.cardBvh) {
        throw std::invalid_argument(std::string("screen probes: surface cache ") +
                                    (view.cards ? "card BVH" : "card") + " buffer missing");
    }
    const gpu::VoxelGridInfo& grid = view.voxelGrid;
    if (!(grid.voxelSize > 0.0f) || grid.dims.x == 0 || grid.dims.y == 0 || grid.dims.z == 0) {
        throw std::invalid_argument("screen probes: surface cache voxel grid has voxel size " +
                                    std::to_string(grid.voxelSize) + " and " + std::to_string(grid.dims.x) +
                                    "x" + std::to_string(grid.dims.y) + "x" + std::to_string(grid.dims.z) +
                                    " voxels (expected > 0)");
    }
}

} // namespace lumina::gi
