#pragma once
// One view of a scene rendered the way a technique asks (docs/gi.md): the deferred renderer,
// and for a GI technique (lumen, DDGI: GiTechniqueRenderer) its GI between the deferred
// lighting and the composite. What `lumina render`,
// `lumina bench` and the viewer run.
//
//   FrameRenderer renderer(device, scene, gpuScene, {.technique = GiTechnique::Lumen, ...});
//   renderer.render(frame);        // every frame
//   renderer.deferred().ldr();     // the image
//
// Dynamic scenes (docs/dynamic_scenes.md): moveInstance, setLights and setEmission (or
// applyScene, which finds what an animated or edited copy of the scene changed) take effect at
// the next render(), which recomputes only what the change touched.
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_gi.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/gi_technique_renderer.h"
#include "gi/frame/lumen_gi.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/sh_grid/sh_grid_gi.h"

#include <memory>
#include <optional>
#include <vector>

namespace lumina::gi {

struct FrameRendererSettings {
    GiTechnique technique = GiTechnique::Lumen;
    DeferredSettings deferred;            // its width and height are the image's (0: the scene's)
    std::optional<LumenSettings> lumen;   // none: lumenPreset(kDefaultPreset, scene)
    std::optional<DdgiSettings> ddgi;     // none: ddgiPreset(kDefaultPreset, scene)
    std::optional<ShGridSettings> shGrid; // none: shGridPreset(kDefaultPreset, scene)
};

// Settings for `technique` at `preset` (one table, preset.h): the preset's shadow maps and the
// technique's own settings for `scene`, at width x height (0: the scene's). What lumina bench, the
// viewer and the tests start from. std::invalid_argument from the presets.
FrameRendererSettings presetRendererSettings(GiTechnique technique, const Preset& preset,
                                             const scene::Scene& scene, uint32_t width = 0,
                                             uint32_t height = 0);

// What the changes applied by the last render() were, for --timings and tests.
struct SceneChangeStats {
    uint32_t movedInstances = 0;
    uint32_t changedLights = 0; // lights edited, added or removed
    uint32_t changedMaterials = 0;
    bool any() const { return movedInstances + changedLights + changedMaterials > 0; }
};

// One frame recorded into three command lists, for async compute (docs/performance.md, change
// 3). `raster` (graphics queue) holds the scene's uploads and the deferred renderer's raster and
// lighting; `async` (a compute-queue list) the GI passes that read nothing the raster writes;
// `gather` (graphics queue) the rest of the GI and the composite. The caller submits `raster`,
// then `async` on the compute queue (waiting for the previous frame's `gather`, whose reads its
// writes must not overtake), then `gather` waiting for `async`.
struct SplitFrame {
    FrameContext& raster;
    FrameContext& async;
    FrameContext& gather;
};

class FrameRenderer {
public:
    // `scene` and `gpuScene` must outlive it. The GPU scene's instances and materials follow the
    // renderer's edits (every renderer sharing it sees them).
    FrameRenderer(rhi::IDevice& device, const scene::Scene& scene, GpuScene& gpuScene,
                  FrameRendererSettings settings);

    void render(FrameContext& frame);
    // The same frame, split for async compute: the same passes with the same results. Returns
    // true when `frame.async` received passes (submit it, and make `gather` wait for it); false
    // when this frame's GI needs the graphics queue throughout (a capture, a light change), and
    // then everything is in `raster` and `gather`.
    bool render(const SplitFrame& frame);
    void setCamera(const scene::Camera& camera);
    // The next frame's GI keeps no temporal history (screen probes and the screen-space
    // filter), so nothing of the old view is reprojected into the new one; the surface cache is
    // view-independent and keeps its lighting. A camera cut in a static scene does not need it:
    // both histories are reprojected in world space and kept only where the surface is the
    // same (the Cornell box recovered within 4 frames so, and within 83 with cameraCut();
    // docs/gi_tests.md). For cuts whose old history must not be reused.
    void cameraCut();

    // Places an instance anew. Throws std::out_of_range for a bad index and
    // std::invalid_argument for a transform that is not finite, is singular, or would mirror an
    // instance that did not (or unmirror one that did: its faces' winding would flip).
    void moveInstance(uint32_t instance, const glm::mat4& transform);
    // The scene's lights from now on: moved, retargeted, recoloured, added or removed. Throws
    // std::invalid_argument for a light with a non-finite or negative value, or more lights than
    // the surface cache's masks hold (128).
    void setLights(std::vector<scene::Light> lights);
    // A material's emitted radiance. Throws std::out_of_range / std::invalid_argument (negative,
    // not finite).
    void setEmission(uint32_t material, const glm::vec3& emission);
    // Applies every difference between `scene` (a copy of the scene this renderer was made
    // from, animated or edited: same meshes, instances and materials) and what the renderer
    // shows: instance transforms, lights, material emission.
    void applyScene(const scene::Scene& scene);

    const std::vector<glm::mat4>& instanceTransforms() const { return transforms_; }
    const std::vector<scene::Light>& lights() const { return deferred_.sceneLights(); }
    // What the last render() applied.
    const SceneChangeStats& lastChanges() const { return lastChanges_; }

    GiTechnique technique() const { return technique_; }
    DeferredRenderer& deferred() { return deferred_; }
    const DeferredRenderer& deferred() const { return deferred_; }
    // The GI technique's renderer; null for the direct technique.
    const GiTechniqueRenderer* gi() const { return gi_.get(); }
    // The technique's own renderer when it is that technique, else null.
    const LumenGi* lumen() const { return dynamic_cast<const LumenGi*>(gi_.get()); }
    const DdgiGi* ddgi() const { return dynamic_cast<const DdgiGi*>(gi_.get()); }
    const ShGridGi* shGrid() const { return dynamic_cast<const ShGridGi*>(gi_.get()); }
    // The indirect term the composite multiplies by indirectScale() x albedo; null without GI.
    rhi::TextureHandle indirect() const { return gi_ ? gi_->indirect() : nullptr; }
    float indirectScale() const;

private:
    void applyPendingChanges(FrameContext& frame);
    scene::Bounds instanceBounds(uint32_t instance, const glm::mat4& transform) const;
    // Every instance's box as transforms_ places them (O(instances): computed when they move).
    scene::Bounds sceneBounds() const;

    const scene::Scene& scene_;
    GpuScene& gpuScene_;
    GiTechnique technique_;
    scene::Camera camera_;
    DeferredRenderer deferred_;
    std::unique_ptr<GiTechniqueRenderer> gi_;

    // The dynamic state the renderer shows, and the edits waiting for the next render().
    std::vector<glm::mat4> transforms_;
    scene::Bounds worldBounds_;                        // of the instances as transforms_ places them
    std::vector<glm::vec3> emissions_;                 // per material
    std::vector<std::vector<uint32_t>> materialUsers_; // per material: instances drawing it
    std::vector<std::pair<uint32_t, glm::mat4>> pendingMoves_;
    std::optional<std::vector<scene::Light>> pendingLights_;
    std::vector<uint32_t> pendingMaterials_;
    SceneChangeStats lastChanges_;
};

} // namespace lumina::gi
