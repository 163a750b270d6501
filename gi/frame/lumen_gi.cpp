#include "gi/frame/lumen_gi.h"

namespace lumina::gi {

LumenGi::LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
                 uint32_t height, const LumenSettings& settings)
    : settings_(settings), sky_(gpuScene.sky), beforeSdf_(device.allocatedMemoryBytes()),
      sdf_(device, scene, settings.sdf), afterSdf_(device.allocatedMemoryBytes()),
      cache_(device, scene, gpuScene, sdf_, settings.cache, settings.lighting),
      afterCache_(device.allocatedMemoryBytes()), probes_(device, width, height, settings.probes),
      afterProbes_(device.allocatedMemoryBytes()) {}

void LumenGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) {
    sdf_.record(frame, camera.position); // the global SDF's cascades follow the camera
    cache_.update(frame, deferred.shadowedLights(), camera.position); // and the cards' LOD
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
