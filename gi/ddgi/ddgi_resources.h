#pragma once
// The GPU memory of a DDGI technique (docs/ddgi.md): every volume's probes, this update's rays,
// the two octahedral atlases they blend into, and the per-pixel irradiance the composite reads.
#include "gi/ddgi/ddgi_volumes.h"
#include "rhi/rhi.h"

#include <cstdint>

namespace lumina::gi {

struct DdgiResources {
    DdgiAtlasLayout layout;
    uint32_t raysPerProbe = 0;
    uint32_t width = 0, height = 0;

    rhi::BufferHandle constants;   // DdgiConstants
    rhi::BufferHandle probes;      // DdgiProbe[layout.probes]: offset and state
    rhi::BufferHandle rayData;     // float4[layout.probes x raysPerProbe]: radiance, signed hit distance
    rhi::TextureHandle irradiance; // RGBA16F, LUMINA_DDGI_IRRADIANCE_TILE^2 per probe: encoded E
    rhi::TextureHandle distance;   // RG16F, LUMINA_DDGI_DISTANCE_TILE^2 per probe: mean distance, its square
    rhi::TextureHandle sampled;    // RGBA16F width x height: irradiance E per pixel
    rhi::SamplerHandle linearClamp;

    uint32_t irradianceWidth() const { return layout.tilesAcross * LUMINA_DDGI_IRRADIANCE_TILE; }
    uint32_t irradianceHeight() const { return layout.tileRows * LUMINA_DDGI_IRRADIANCE_TILE; }
    uint32_t distanceWidth() const { return layout.tilesAcross * LUMINA_DDGI_DISTANCE_TILE; }
    uint32_t distanceHeight() const { return layout.tileRows * LUMINA_DDGI_DISTANCE_TILE; }

    static DdgiResources create(rhi::IDevice& device, const DdgiAtlasLayout& layout, uint32_t raysPerProbe,
                                uint32_t width, uint32_t height);
};

} // namespace lumina::gi
