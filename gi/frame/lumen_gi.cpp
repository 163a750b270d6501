#include "gi/frame/lumen_gi.h"

namespace lumina::gi {

LumenGi::LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
                 uint32_t height, const LumenSettings& settings)
    : settings_(settings), sky_(scene.sky), sdf_(device, scene, settings.sdf),
      cache_(device, scene, gpuScene, sdf_, settings.cache, settings.lighting),
      probes_(device, width, height, settings.probes) {}

void LumenGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) {
    sdf_.record(frame);
    cache_.update(frame, deferred.shadowedLights());
    const gpu::VoxelGridInfo& grid = cache_.voxelLighting().grid();
    const glm::vec3 boxMin(grid.minAndVoxelSize.x, grid.minAndVoxelSize.y, grid.minAndVoxelSize.z);
    const glm::vec3 boxMax =
        boxMin + grid.minAndVoxelSize.w * glm::vec3(grid.dims.x, grid.dims.y, grid.dims.z);
    probes_.record(frame, {.gbuffer = deferred.gbuffer(),
                           .camera = camera,
                           .sdf = sdf_,
                           .sky = sky_,
                           .voxelLighting = {.texture = cache_.voxelLighting().volume(),
                                             .boxMin = boxMin,
                                             .boxMax = boxMax,
                                             .faces = LUMINA_VOXEL_FACES}});
}

} // namespace lumina::gi
