#pragma once
// The screen-probe final gather (docs/screen_probes.md): the view-dependent half of the GI.
// Records, every frame, one named and timed pass each:
//
//   placement -> brdf pdf -> lighting pdf -> mis directions -> trace far field -> shade rays
//   -> composite -> temporal -> spatial filter -> sh irradiance -> final gather -> screen temporal
//
//   ScreenProbeGather probes(device, width, height, settings);
//   probes.record(frame, {.gbuffer = renderer.gbuffer(), .camera = camera, .sdf = sdfs,
//                         .sky = scene.sky, .voxelLighting = {volume, boxMin, boxMax}});
//   probes.irradiance();   // RGBA16F: rgb irradiance per pixel (0 on sky)
//
// The GBuffer must hold the frame `camera` describes. The SceneSdf must have recorded its
// global SDF before (SceneSdf::record). History follows the camera by reprojection; call
// resetHistory() on a cut.
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
#include "gi/screen_probes/screen_gather_pass.h"
#include "gi/screen_probes/screen_probe_placement_pass.h"
#include "gi/screen_probes/screen_probe_resources.h"
#include "gi/screen_probes/screen_temporal_pass.h"
#include "gi/sdf/scene_sdf.h"
#include "shaders/common/camera_shared.h"

#include <glm/glm.hpp>
#include <optional>

namespace lumina::gi {

// Radiance at far-field hits: an RGBA16F 3D texture over a world box, rgb the radiance leaving
// the surfaces in a voxel premultiplied by a, its occupancy (0: empty). The surface cache fills it.
struct VoxelLighting {
    rhi::TextureHandle texture; // null: none (hits are black)
    glm::vec3 boxMin{0.0f};
    glm::vec3 boxMax{0.0f};
    // 1: one radiance per voxel; LUMINA_VOXEL_FACES (the surface cache's): the texture holds that
    // many face columns side by side along x, read by the hit normal (surface_cache_lighting_shared.h).
    uint32_t faces = 1;
};

struct ScreenProbeInputs {
    const GBuffer& gbuffer;
    const scene::Camera& camera;
    const sdf::SceneSdf& sdf;
    glm::vec3 sky{0.0f}; // uniform radiance of rays that leave the scene
    VoxelLighting voxelLighting;
};

class ScreenProbeGather {
public:
    // Throws std::invalid_argument for bad settings or size, naming the value.
    ScreenProbeGather(rhi::IDevice& device, uint32_t width, uint32_t height,
                      ScreenProbeSettings settings = {});

    void record(FrameContext& frame, const ScreenProbeInputs& inputs);
    // The next frame starts without history (a camera cut, a teleport).
    void resetHistory() { previousCamera_.reset(); }

    // This frame's result: rgb irradiance (pi x L under a uniform radiance L), a = frames accumulated.
    const rhi::TextureHandle& irradiance() const { return resources_.screenIrradiance[current_]; }
    const ScreenProbeResources& resources() const { return resources_; }
    const ScreenProbeSettings& settings() const { return settings_; }
    // The ping-pong half this frame wrote (probes, history, screen irradiance and positions).
    uint32_t current() const { return current_; }
    uint64_t framesRecorded() const { return frames_; }
    // Rays per probe drawn from the BRDF table; the rest come from the lighting table.
    uint32_t brdfRays() const;

private:
    void uploadConstants(rhi::ICommandList& commands, const ScreenProbeInputs& inputs,
                         const gpu::GpuCamera& camera);

    ScreenProbeSettings settings_;
    ScreenProbeResources resources_;
    uint32_t current_ = 1; // flips before each frame: the first frame writes half 0
    uint64_t frames_ = 0;
    bool voxelFallbackCleared_ = false;
    std::optional<gpu::GpuCamera> previousCamera_;

    ScreenProbePlacementPass placement_;
    ProbeBrdfPdfPass brdfPdf_;
    ProbeLightingPdfPass lightingPdf_;
    ProbeRayGenerationPass rayGeneration_;
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
