#pragma once
// The lumen technique's GI for one view (docs/gi.md): the scene's SDFs, its surface cache and
// the screen-probe gather, recorded between the deferred renderer's lighting and composite:
//
//   deferred lighting ─► sdf compose ─► surface cache update ─► screen probes ─► composite
//                                       (lit by the deferred     (read the GBuffer, the SDFs
//                                        renderer's lights)       and the voxel lighting)
//
//   LumenGi gi(device, scene, gpuScene, width, height, lumenPreset("medium", scene));
//   deferred.recordLighting(frame);
//   gi.record(frame, deferred, camera);
//   deferred.setIndirect(gi.irradiance(), 1 / pi);
//   deferred.recordComposite(frame);
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_technique.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "gi/screen_probes/screen_probe_gather.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/surface_cache.h"

#include <span>

namespace lumina::gi {

// GPU memory each subsystem allocated when it was built (device allocation deltas), bytes.
struct LumenMemory {
    uint64_t sdf = 0;          // mesh SDF atlas, instance tables, global SDF
    uint64_t surfaceCache = 0; // atlas layers, capture depth, voxel lighting, radiosity probes
    uint64_t screenProbes = 0; // probe buffers and the screen-space histories
};

class LumenGi {
public:
    // `scene` and `gpuScene` must outlive it. Builds (or loads from the cache) the mesh SDFs;
    // throws std::invalid_argument for bad settings and what the subsystems throw (a full
    // atlas names the card that did not fit).
    LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
            uint32_t height, const LumenSettings& settings);

    // After deferred.recordLighting(frame) of the frame `camera` shows.
    void record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera);
    // The next frame's probes start without history (a camera cut).
    void resetHistory() { probes_.resetHistory(); }

    // A dynamic scene's changes, recorded at the next record() (FrameRenderer applies them).
    // An instance moved from `before` to `after` (world boxes): its SDF region is recomposed, its
    // cards placed anew and captured, radiosity restarts near it, and history there is dropped.
    void moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                      const scene::Bounds& after, std::span<const scene::Light> lights);
    // The lights changed (DeferredRenderer::setLights made `lightsVersion`); `reach` holds the
    // world boxes the changed lights reached before or reach now.
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                   std::span<const scene::Bounds> reach);
    // A material the instance draws changed (emission); `reach` is where its light may land.
    void instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach);

    // RGBA16F irradiance E per pixel (0 on sky); the composite wants E / pi.
    const rhi::TextureHandle& irradiance() const { return probes_.irradiance(); }
    const sdf::SceneSdf& sdf() const { return sdf_; }
    const surface_cache::SurfaceCache& surfaceCache() const { return cache_; }
    const ScreenProbeGather& screenProbes() const { return probes_; }
    const LumenSettings& settings() const { return settings_; }
    LumenMemory memory() const {
        return {afterSdf_ - beforeSdf_, afterCache_ - afterSdf_, afterProbes_ - afterCache_};
    }

private:
    // The allocation marks are members between the subsystems so that members' construction
    // order measures each one.
    LumenSettings settings_;
    rhi::TextureHandle sky_; // the GpuScene's: what probe rays that leave the scene see
    uint64_t beforeSdf_;
    sdf::SceneSdf sdf_;
    uint64_t afterSdf_;
    surface_cache::SurfaceCache cache_;
    uint64_t afterCache_;
    ScreenProbeGather probes_;
    uint64_t afterProbes_;
};

} // namespace lumina::gi
