#pragma once
// One view of a scene rendered the way a technique asks (docs/gi.md): the deferred renderer,
// and for lumen its GI between the deferred lighting and the composite. What `lumina render`
// and `lumina bench` run.
//
//   FrameRenderer renderer(device, scene, gpuScene, {.technique = GiTechnique::Lumen, ...});
//   renderer.render(frame);        // every frame
//   renderer.deferred().ldr();     // the image
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/lumen_gi.h"
#include "gi/gpu_scene/gpu_scene.h"

#include <memory>
#include <optional>

namespace lumina::gi {

struct FrameRendererSettings {
    GiTechnique technique = GiTechnique::Lumen;
    DeferredSettings deferred;          // its width and height are the image's (0: the scene's)
    std::optional<LumenSettings> lumen; // none: lumenPreset(kDefaultPreset, scene)
};

class FrameRenderer {
public:
    // `scene` and `gpuScene` must outlive it.
    FrameRenderer(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                  FrameRendererSettings settings);

    void render(FrameContext& frame);
    void setCamera(const scene::Camera& camera);
    // The next frame's GI keeps no temporal history (screen probes and the screen-space
    // filter), so nothing of the old view is reprojected into the new one; the surface cache is
    // view-independent and keeps its lighting. A camera cut in a static scene does not need it:
    // both histories are reprojected in world space and kept only where the surface is the
    // same (the Cornell box recovered within 4 frames so, and within 83 with cameraCut();
    // docs/gi_tests.md). For cuts whose old history must not be reused.
    void cameraCut();

    GiTechnique technique() const { return technique_; }
    DeferredRenderer& deferred() { return deferred_; }
    const DeferredRenderer& deferred() const { return deferred_; }
    // Null for the direct technique.
    const LumenGi* lumen() const { return lumen_.get(); }
    // The indirect term the composite multiplies by indirectScale() x albedo; null without GI.
    rhi::TextureHandle indirect() const { return lumen_ ? lumen_->irradiance() : nullptr; }
    float indirectScale() const;

private:
    GiTechnique technique_;
    scene::Camera camera_;
    DeferredRenderer deferred_;
    std::unique_ptr<LumenGi> lumen_;
};

} // namespace lumina::gi
