#include "gi/frame/lumen_gi.h"

namespace lumina::gi {

LumenGi::LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
                 uint32_t height, const LumenSettings& settings)
    : settings_(settings), scene_(device, scene, gpuScene, settings),
      beforeProbes_(device.allocatedMemoryBytes()), probes_(device, width, height, settings.probes),
      afterProbes_(device.allocatedMemoryBytes()) {}

bool LumenGi::recordBesideRaster(FrameContext& async, const DeferredRenderer& deferred,
                                 const scene::Camera& camera) {
    if (!scene_.recordIsComputeOnly(deferred, camera)) {
        return false;
    }
    scene_.record(async, deferred, camera);
    sceneRecordedBesideRaster_ = true;
    return true;
}

void LumenGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) {
    if (!sceneRecordedBesideRaster_) {
        scene_.record(frame, deferred, camera);
    }
    sceneRecordedBesideRaster_ = false;
    // Near-field hits read their cards' final lighting, far-field hits the cache's voxel lighting
    // (no volume of its own).
    const VoxelLighting cacheVoxels{};
    const ScreenProbeInputs inputs{.gbuffer = deferred.gbuffer(),
                                   .camera = camera,
                                   .sdf = scene_.sdf(),
                                   .sky = scene_.sky(),
                                   .voxelLighting = cacheVoxels,
                                   .surfaceCache = scene_.surfaceCacheView()};
    probes_.record(frame, inputs);
}

std::vector<GiMemoryPart> LumenGi::memory() const {
    std::vector<GiMemoryPart> parts = scene_.memory();
    parts.push_back({"screen probes", afterProbes_ - beforeProbes_});
    return parts;
}

std::vector<GiDebugTexture> LumenGi::debugTextures() const {
    // Lumen's buffers have views of their own (app/viewer/gi_views.cpp: SDF slices and traces,
    // card outlines, radiosity probes, the screen probes' maps) and dumps (frame_dump.cpp).
    return {};
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
    scene_.moveInstance(instance, transform, lights);
    probes_.invalidateHistory(grown(before, kHistoryMarginFraction), 0.0f);
    probes_.invalidateHistory(grown(after, kHistoryMarginFraction), 0.0f);
}

void LumenGi::setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                        std::span<const scene::Bounds> reach) {
    scene_.setLights(lights, lightsVersion);
    for (const scene::Bounds& box : reach) {
        probes_.invalidateHistory(box, kLightChangeHistoryKeep);
    }
}

void LumenGi::instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) {
    scene_.instanceMaterialChanged(instance);
    probes_.invalidateHistory(reach, kLightChangeHistoryKeep);
}

} // namespace lumina::gi
