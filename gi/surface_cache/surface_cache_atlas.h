#pragma once
// The surface-cache atlas on the GPU: six layers of settings.atlasSize² texels, addressed by the
// cards' atlas rectangles (texels; every layer shares them).
//
//   layer            format     written by                    holds
//   Albedo           RGBA16F    card capture (render target)  linear albedo (rounded down); a = 1 where
//   captured Normal           RGBA16F    card capture (render target)  unit world normal towards the card; a
//   = 1 where captured Material         RGBA16F    card capture (render target)  emitted radiance; a =
//   material index DirectLight      RGBA16F    direct-light update (UAV)     irradiance (raw, no albedo / pi)
//   IndirectLight    RGBA16F    radiosity (UAV)               irradiance
//   FinalLighting    RGBA16F    combine (UAV)                 outgoing radiance, read by ray hits
//
// Not one six-layer array, for two reasons: the layers of one array may need different formats, and the
// RHI tracks state per texture, so a pass could not read one layer of an array while it writes
// another (the direct-light update reads Normal and writes DirectLight). The layers are grouped
// instead by who writes them together: Normal and Material are the two layers of one RGBA16F
// Texture2DArray (the capture writes both), every other layer is a texture of its own.
#include "gi/surface_cache/surface_cache_settings.h"
#include "rhi/rhi.h"

#include <array>
#include <cstdint>

namespace lumina::surface_cache {

enum class AtlasLayer : uint32_t { Albedo, Normal, Material, DirectLight, IndirectLight, FinalLighting };
inline constexpr uint32_t kAtlasLayerCount = 6;
const char* atlasLayerName(AtlasLayer layer);

// Where a layer lives: a texture, and the array layer within it.
struct AtlasLayerView {
    rhi::TextureHandle texture;
    uint32_t arrayLayer = 0;
};

class SurfaceCacheAtlas {
public:
    // Creates the layers (throws std::invalid_argument for bad settings, rhi::Error when the
    // device cannot make them); their contents are undefined until recordClear has run.
    SurfaceCacheAtlas(rhi::IDevice& device, const SurfaceCacheSettings& settings);

    // Clears every layer to zero, so that texels no card covers read as "no surface, no light".
    void recordClear(rhi::ICommandList& commands) const;

    AtlasLayerView layer(AtlasLayer layer) const { return layers_[uint32_t(layer)]; }
    uint32_t size() const { return size_; }
    // Bytes of GPU memory the layers take.
    uint64_t bytes() const;

    rhi::TextureHandle albedo;   // RGBA16_FLOAT Texture2D (not RGBA8: see docs/surface_cache.md)
    rhi::TextureHandle surface;  // RGBA16_FLOAT Texture2DArray: layer 0 normal, 1 material
    rhi::TextureHandle direct;   // RGBA16_FLOAT Texture2D
    rhi::TextureHandle indirect; // RGBA16_FLOAT Texture2D
    rhi::TextureHandle final;    // RGBA16_FLOAT Texture2D

private:
    uint32_t size_ = 0;
    std::array<AtlasLayerView, kAtlasLayerCount> layers_;
};

} // namespace lumina::surface_cache
