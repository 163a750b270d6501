#pragma once
// Hit records to radiance: near-field hits bring the surface cache's, misses see the sky,
// far-field hits read the voxel lighting volume.
// Kernel: shaders/screen_probes/probe_ray_shading.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeRayShadingPass {
public:
    static constexpr const char* kName = "screen probes: shade rays";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
