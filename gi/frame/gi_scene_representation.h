#pragma once
// What every SDF-traced GI technique (lumen, DDGI) builds its rays on (docs/gi.md): the scene's
// SDFs and its surface cache, updated once a frame and kept current as the scene changes. Each
// technique owns one and reads it through sdf() and surfaceCacheView():
//
//   GiSceneRepresentation scene(device, scene, gpuScene, settings); // settings: GiSceneSettings
//   scene.record(frame, deferred, camera);   // global SDF follows the camera, cards relit
//   tracePass(frame, scene.sdf(), scene.surfaceCacheView());
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_technique_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/screen_probes/surface_cache_view.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/surface_cache.h"

#include <span>
#include <vector>

namespace lumina::gi {

class GiSceneRepresentation {
public:
    // `scene` and `gpuScene` must outlive it. Builds (or loads from the cache) the mesh SDFs;
    // throws what SceneSdf and SurfaceCache throw for bad settings.
    GiSceneRepresentation(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                          const GiSceneSettings& settings);

    // The global SDF's cascades and the cards' LOD follow the camera; the cards are lit by the
    // deferred renderer's shadowed lights (after its recordLighting this frame).
    void record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera);
    // True when this frame's record() would be compute work only, reading nothing of the frame's
    // raster (no card capture, no card lit from a shadow map rendered this frame): it may then
    // go on the async compute queue. Plans the cards' levels for `camera` first.
    bool recordIsComputeOnly(const DeferredRenderer& deferred, const scene::Camera& camera);

    void moveInstance(uint32_t instance, const glm::mat4& transform, std::span<const scene::Light> lights);
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion);
    void instanceMaterialChanged(uint32_t instance);

    const sdf::SceneSdf& sdf() const { return sdf_; }
    const surface_cache::SurfaceCache& surfaceCache() const { return cache_; }
    SurfaceCacheView surfaceCacheView() const { return gi::surfaceCacheView(cache_); }
    // What the tracing needs of the sky: the GpuScene's (every ray that leaves the scene sees it).
    const rhi::TextureHandle& sky() const { return sky_; }
    bool settled() const { return cache_.settled(); }
    // "SDFs" and "surface cache".
    std::vector<GiMemoryPart> memory() const;

private:
    // The allocation marks are members between the subsystems so that members' construction
    // order measures each one.
    rhi::TextureHandle sky_;
    uint64_t beforeSdf_;
    sdf::SceneSdf sdf_;
    uint64_t afterSdf_;
    surface_cache::SurfaceCache cache_;
    uint64_t afterCache_;
};

} // namespace lumina::gi
