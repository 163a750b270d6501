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

namespace {

// History near a change is dropped within this many times the changed box's size around it: the
// light a moved object blocks or bounces lands next to it (a contact shadow, a colour bleed).
constexpr float kHistoryMarginFraction = 0.5f;
// The share of history weight kept where a light changed: the surface cache re-lights its cards
// at once but radiosity takes a few frames, so history is only shortened, not dropped.
constexpr float kLightChangeHistoryKeep = 0.25f;

scene::Bounds grown(const scene::Bounds& box, float fraction) {
    const float margin = fraction * glm::length(box.size());
    return {box.min - glm::vec3(margin), box.max + glm::vec3(margin)};
}

} // namespace

void LumenGi::moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                           const scene::Bounds& after, std::span<const scene::Light> lights) {
    sdf_.setInstanceTransform(instance, transform);
    cache_.moveInstance(instance, transform, lights);
    probes_.invalidateHistory(grown(before, kHistoryMarginFraction), 0.0f);
    probes_.invalidateHistory(grown(after, kHistoryMarginFraction), 0.0f);
}

void LumenGi::setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                        std::span<const scene::Bounds> reach) {
    cache_.setLights(lights, lightsVersion);
    for (const scene::Bounds& box : reach) {
        probes_.invalidateHistory(box, kLightChangeHistoryKeep);
    }
}

void LumenGi::instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) {
    cache_.instanceMaterialChanged(instance);
    probes_.invalidateHistory(reach, kLightChangeHistoryKeep);
}

} // namespace lumina::gi
