#include "gi/frame/gi_scene_representation.h"

namespace lumina::gi {

GiSceneRepresentation::GiSceneRepresentation(rhi::IDevice& device, const scene::Scene& scene,
                                             const GpuScene& gpuScene, const GiSceneSettings& settings)
    : sky_(gpuScene.sky), beforeSdf_(device.allocatedMemoryBytes()), sdf_(device, scene, settings.sdf),
      afterSdf_(device.allocatedMemoryBytes()),
      cache_(device, scene, gpuScene, sdf_, settings.cache, settings.lighting),
      afterCache_(device.allocatedMemoryBytes()) {}

void GiSceneRepresentation::record(FrameContext& frame, const DeferredRenderer& deferred,
                                   const scene::Camera& camera) {
    sdf_.record(frame, camera.position);
    cache_.update(frame, deferred.shadowedLights(), camera.position);
}

bool GiSceneRepresentation::recordIsComputeOnly(const DeferredRenderer& deferred,
                                                const scene::Camera& camera) {
    // The SDFs' update is compute and copies only (compose, brick tables).
    cache_.planLod(camera.position);
    return cache_.updateIsComputeOnly(deferred.shadowedLights());
}

void GiSceneRepresentation::moveInstance(uint32_t instance, const glm::mat4& transform,
                                         std::span<const scene::Light> lights) {
    sdf_.setInstanceTransform(instance, transform);
    cache_.moveInstance(instance, transform, lights);
}

void GiSceneRepresentation::setLights(std::span<const scene::Light> lights, uint64_t lightsVersion) {
    cache_.setLights(lights, lightsVersion);
}

void GiSceneRepresentation::instanceMaterialChanged(uint32_t instance) {
    cache_.instanceMaterialChanged(instance);
}

std::vector<GiMemoryPart> GiSceneRepresentation::memory() const {
    return {{"SDFs", afterSdf_ - beforeSdf_}, {"surface cache", afterCache_ - afterSdf_}};
}

} // namespace lumina::gi
