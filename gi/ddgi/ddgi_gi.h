#pragma once
// The DDGI technique (docs/ddgi.md): probe volumes whose rays are sphere-traced through the same
// SDFs and surface cache lumen uses, blended into octahedral irradiance and distance maps, and
// sampled per pixel with Chebyshev visibility. Recorded between the deferred lighting and the
// composite:
//
//   deferred lighting ─► sdf compose ─► surface cache ─► reset ─► trace ─► blend irradiance
//       ─► blend distance ─► relocate ─► classify ─► sample ─► composite
//
//   DdgiGi gi(device, scene, gpuScene, width, height, ddgiPreset("medium", scene));
//   gi.record(frame, deferred, camera);
//   deferred.setIndirect(gi.indirect(), gi.indirectScale());
#include "gi/ddgi/ddgi_blend_distance_pass.h"
#include "gi/ddgi/ddgi_blend_irradiance_pass.h"
#include "gi/ddgi/ddgi_classify_pass.h"
#include "gi/ddgi/ddgi_relocate_pass.h"
#include "gi/ddgi/ddgi_reset_pass.h"
#include "gi/ddgi/ddgi_resources.h"
#include "gi/ddgi/ddgi_sample_pass.h"
#include "gi/ddgi/ddgi_settings.h"
#include "gi/ddgi/ddgi_trace_pass.h"
#include "gi/ddgi/ddgi_volumes.h"
#include "gi/frame/gi_scene_representation.h"
#include "gi/frame/gi_technique_renderer.h"

#include <random>
#include <vector>

namespace lumina::gi {

// How many probes are in each state (ddgi_shared.h), read back from the GPU.
struct DdgiProbeCounts {
    uint32_t fresh = 0;
    uint32_t active = 0;
    uint32_t inactive = 0; // classified off: their rays beyond the fixed set and their blends skipped
    uint32_t total() const { return fresh + active + inactive; }
};

class DdgiGi final : public GiTechniqueRenderer {
public:
    // `scene` and `gpuScene` must outlive it. std::invalid_argument for bad settings (named), and
    // what the SDFs and the surface cache throw.
    DdgiGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
           uint32_t height, const DdgiSettings& settings);

    GiTechnique technique() const override { return GiTechnique::Ddgi; }
    void record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) override;
    // The SDF and surface cache update and the probes' update (everything but the sample pass,
    // which reads the GBuffer), when the surface cache's update is compute work only this frame.
    bool recordBesideRaster(FrameContext& async, const DeferredRenderer& deferred,
                            const scene::Camera& camera) override;
    // Probes hold world-space irradiance, nothing of the view: a camera cut keeps them.
    void resetHistory() override {}
    // The surface cache has converged; the probes follow within a few hundred / (1 - hysteresis)
    // updates (the tests lower the hysteresis to converge sooner).
    bool converged() const override { return scene_.settled(); }

    void moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                      const scene::Bounds& after, std::span<const scene::Light> lights) override;
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                   std::span<const scene::Bounds> reach) override;
    void instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) override;

    rhi::TextureHandle indirect() const override { return resources_.sampled; }
    std::vector<GiMemoryPart> memory() const override;
    std::vector<GiDebugTexture> debugTextures() const override;

    // Every probe's state (waits for the GPU).
    DdgiProbeCounts probeCounts(rhi::IDevice& device) const;
    const DdgiResources& resources() const { return resources_; }
    const std::vector<DdgiVolumePlacement>& volumes() const { return volumes_; }
    const DdgiSettings& settings() const { return settings_; }
    const sdf::SceneSdf& sdf() const { return scene_.sdf(); }
    const surface_cache::SurfaceCache& surfaceCache() const { return scene_.surfaceCache(); }
    uint64_t updates() const { return updates_; }

private:
    // Places the volumes for this update (cascades follow the camera, scrolling) and uploads the
    // constants; true when some volume's probes are to be reset (all, or the planes scrolled in).
    bool uploadConstants(rhi::ICommandList& commands, const scene::Camera& camera);
    // The scene's update and the probes' trace, blends, relocation and classification.
    void recordProbeUpdate(FrameContext& frame, const DeferredRenderer& deferred,
                           const scene::Camera& camera);

    DdgiSettings settings_;
    GiSceneRepresentation scene_;
    scene::Bounds sceneBox_;
    std::vector<DdgiVolumePlacement> volumes_;
    uint64_t beforeProbes_;
    DdgiResources resources_;
    uint64_t afterProbes_;
    std::vector<glm::uvec3> scrolls_; // per volume: DdgiVolumeInfo::scroll
    std::mt19937 random_;
    uint64_t updates_ = 0;
    bool probesRecordedBesideRaster_ = false; // this frame's probe update went to the async list

    DdgiResetPass reset_;
    DdgiTracePass trace_;
    DdgiBlendIrradiancePass blendIrradiance_;
    DdgiBlendDistancePass blendDistance_;
    DdgiRelocatePass relocate_;
    DdgiClassifyPass classify_;
    DdgiSamplePass sample_;
};

} // namespace lumina::gi
