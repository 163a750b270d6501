#pragma once
// The screen-probe final gather (docs/screen_probes.md): the view-dependent half of the GI.
// Records, every frame, one named and timed pass each:
//
//   placement -> adaptive placement -> adaptive allocation -> brdf pdf -> lighting pdf
//   -> mis directions -> trace near field -> trace far field -> shade rays -> composite
//   -> temporal -> spatial filter -> sh irradiance -> final gather -> screen temporal
//
//   ScreenProbeGather probes(device, width, height, settings);
//   probes.record(frame, {.gbuffer = renderer.gbuffer(), .camera = camera, .sdf = sdfs,
//                         .sky = gpuScene.sky, .surfaceCache = gi::surfaceCacheView(cache)});
//   probes.irradiance();   // RGBA32F: rgb irradiance per pixel (0 on sky)
//
// The GBuffer must hold the frame `camera` describes. The SceneSdf must have recorded its
// global SDF before (SceneSdf::record), the surface cache its update. History follows the camera
// by reprojection; call resetHistory() on a cut.
#include "gi/core/frame_context.h"
#include "gi/deferred/gbuffer_pass.h"
#include "gi/scene/scene.h"
#include "gi/screen_probes/probe_brdf_pdf_pass.h"
#include "gi/screen_probes/probe_composite_pass.h"
#include "gi/screen_probes/probe_lighting_pdf_pass.h"
#include "gi/screen_probes/probe_ray_generation_pass.h"
#include "gi/screen_probes/probe_ray_shading_pass.h"
#include "gi/screen_probes/probe_sh_irradiance_pass.h"
#include "gi/screen_probes/probe_spatial_filter_pass.h"
#include "gi/screen_probes/probe_temporal_pass.h"
#include "gi/screen_probes/probe_trace_far_field_pass.h"
#include "gi/screen_probes/probe_trace_near_field_pass.h"
#include "gi/screen_probes/screen_gather_pass.h"
#include "gi/screen_probes/screen_probe_adaptive_allocation_pass.h"
#include "gi/screen_probes/screen_probe_adaptive_placement_pass.h"
#include "gi/screen_probes/screen_probe_placement_pass.h"
#include "gi/screen_probes/screen_probe_resources.h"
#include "gi/screen_probes/screen_temporal_pass.h"
#include "gi/screen_probes/surface_cache_view.h"
#include "gi/sdf/scene_sdf.h"
#include "shaders/common/camera_shared.h"

#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace lumina::gi {

// Radiance at far-field hits: an RGBA16F 3D texture over a world box, rgb the radiance leaving
// the surfaces in a voxel premultiplied by a, its occupancy (0: empty). A surface cache passed as
// ScreenProbeInputs::surfaceCache stands in for it (with its own grid and lookup) when none is given.
struct VoxelLighting {
    rhi::TextureHandle texture; // null: none (hits are black)
    glm::vec3 boxMin{0.0f};
    glm::vec3 boxMax{0.0f};
};

struct ScreenProbeInputs {
    const GBuffer& gbuffer;
    const scene::Camera& camera;
    const sdf::SceneSdf& sdf;
    // What rays that leave the scene see: a latitude-longitude RGBA32F texture, usually the
    // GpuScene's sky (gi/gpu_scene/sky_texture.h). Required.
    rhi::TextureHandle sky;
    // Far-field hits read this volume; without one they read the surface cache's voxel lighting
    // (when given), else they are black.
    VoxelLighting voxelLighting;
    // The near field reads it (settings.nearFieldDistance); none: no near field, the far field
    // traces every ray from the probe.
    std::optional<SurfaceCacheView> surfaceCache = std::nullopt;
};

class ScreenProbeGather {
public:
    // Throws std::invalid_argument for bad settings or size, naming the value.
    ScreenProbeGather(rhi::IDevice& device, uint32_t width, uint32_t height,
                      ScreenProbeSettings settings = {});

    void record(FrameContext& frame, const ScreenProbeInputs& inputs);
    // The next frame starts without history (a camera cut, a teleport).
    void resetHistory() { previousCamera_.reset(); }
    // The scene changed within `region` (world box): at the next frame, probe and screen history
    // there keep only `keep` (0..1) of their weight, so the old light does not trail behind a moved
    // object or a changed light. More regions than the constants hold are merged.
    void invalidateHistory(const scene::Bounds& region, float keep);

    // This frame's result: rgb irradiance (pi x L under a uniform radiance L), a = frames accumulated.
    const rhi::TextureHandle& irradiance() const { return resources_.screenIrradiance[current_]; }
    const ScreenProbeResources& resources() const { return resources_; }
    const ScreenProbeSettings& settings() const { return settings_; }
    // The ping-pong half this frame wrote (probes, history, screen irradiance and positions).
    uint32_t current() const { return current_; }
    uint64_t framesRecorded() const { return frames_; }
    // Whether the last frame traced the near field (resources().nearField holds its result).
    bool nearFieldTraced() const { return nearFieldTraced_; }
    // Adaptive tiles that asked for a probe in the last frame recorded (read back: call after it ran);
    // those past the adaptive slots went without.
    uint32_t adaptiveProbesWanted(rhi::IDevice& device) const;
    // Rays per probe drawn from the BRDF table; the rest come from the lighting table.
    uint32_t brdfRays() const;

private:
    // How far rays go: the whole trace, and the near field's part of it (0: no near field).
    struct TraceRange {
        float maxDistance = 0.0f;
        float nearField = 0.0f;
    };
    TraceRange traceRange(const ScreenProbeInputs& inputs) const;
    void uploadConstants(rhi::ICommandList& commands, const ScreenProbeInputs& inputs,
                         const gpu::GpuCamera& camera, const TraceRange& range);

    ScreenProbeSettings settings_;
    ScreenProbeResources resources_;
    uint32_t current_ = 1; // flips before each frame: the first frame writes half 0
    uint64_t frames_ = 0;
    bool voxelFallbackCleared_ = false;
    bool nearFieldTraced_ = false;
    std::optional<gpu::GpuCamera> previousCamera_;
    struct ChangeRegion {
        scene::Bounds box;
        float keep = 0.0f;
    };
    std::vector<ChangeRegion> changes_; // until the next record()

    ScreenProbePlacementPass placement_;
    ScreenProbeAdaptivePlacementPass adaptivePlacement_;
    ScreenProbeAdaptiveAllocationPass adaptiveAllocation_;
    ProbeBrdfPdfPass brdfPdf_;
    ProbeLightingPdfPass lightingPdf_;
    ProbeRayGenerationPass rayGeneration_;
    ProbeTraceNearFieldPass traceNearField_;
    ProbeTraceFarFieldPass traceFarField_;
    ProbeRayShadingPass rayShading_;
    ProbeCompositePass composite_;
    ProbeTemporalPass temporal_;
    ProbeSpatialFilterPass spatialFilter_;
    ProbeShIrradiancePass shIrradiance_;
    ScreenGatherPass gather_;
    ScreenTemporalPass screenTemporal_;
};

} // namespace lumina::gi
