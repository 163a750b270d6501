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
//   deferred.setIndirect(gi.indirect(), gi.indirectScale());
//   deferred.recordComposite(frame);
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_scene_representation.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/gi_technique_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "gi/screen_probes/screen_probe_gather.h"

#include <span>

namespace lumina::gi {

class LumenGi final : public GiTechniqueRenderer {
public:
    // `scene` and `gpuScene` must outlive it. Builds (or loads from the cache) the mesh SDFs;
    // throws std::invalid_argument for bad settings and what the subsystems throw (a full
    // atlas names the card that did not fit).
    LumenGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
            uint32_t height, const LumenSettings& settings);

    GiTechnique technique() const override { return GiTechnique::Lumen; }
    void record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) override;
    // The SDF and surface cache update, when it is compute work only this frame.
    bool recordBesideRaster(FrameContext& async, const DeferredRenderer& deferred,
                            const scene::Camera& camera) override;
    // The next frame's probes start without history (a camera cut).
    void resetHistory() override { probes_.resetHistory(); }
    // The surface cache's radiosity has converged (the screen probes follow within frames).
    bool converged() const override { return scene_.settled(); }

    // An instance moved: its SDF region is recomposed, its cards placed anew and captured,
    // radiosity restarts near it, and history there is dropped.
    void moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                      const scene::Bounds& after, std::span<const scene::Light> lights) override;
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                   std::span<const scene::Bounds> reach) override;
    void instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) override;

    // The screen probes' RGBA32F irradiance E per pixel (0 on sky).
    rhi::TextureHandle indirect() const override { return probes_.irradiance(); }
    std::vector<GiMemoryPart> memory() const override;
    std::vector<GiDebugTexture> debugTextures() const override;

    const sdf::SceneSdf& sdf() const { return scene_.sdf(); }
    const surface_cache::SurfaceCache& surfaceCache() const { return scene_.surfaceCache(); }
    const ScreenProbeGather& screenProbes() const { return probes_; }
    const LumenSettings& settings() const { return settings_; }

private:
    LumenSettings settings_;
    GiSceneRepresentation scene_;
    bool sceneRecordedBesideRaster_ = false; // this frame's scene update went to the async list
    uint64_t beforeProbes_;
    ScreenProbeGather probes_;
    uint64_t afterProbes_;
};

} // namespace lumina::gi
