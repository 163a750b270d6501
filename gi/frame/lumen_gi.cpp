#include "gi/frame/lumen_gi.h"

namespace lumina::gi {

LumenGi::LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
                 uint32_t height, const LumenSettings& settings)
    : settings_(settings), sky_(gpuScene.sky), sdf_(device, scene, settings.sdf),
      cache_(device, scene, gpuScene, sdf_, settings.cache, settings.lighting),
      probes_(device, width, height, settings.probes) {}

void LumenGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) {
    sdf_.record(frame);
    cache_.update(frame, deferred.shadowedLights());
    // Near-field hits read their cards' final lighting, far-field hits the cache's voxel lighting
    // (no volume of its own).
    const VoxelLighting cacheVoxels{};
    const ScreenProbeInputs inputs{.gbuffer = deferred.gbuffer(),
                                   .camera = camera,
                                   .sdf = sdf_,
                                   .sky = sky_,
                                   .voxelLighting = cacheVoxels,
                                   .surfaceCache = surfaceCacheView(cache_)};
    probes_.record(frame, inputs);
}

} // namespace lumina::gi
