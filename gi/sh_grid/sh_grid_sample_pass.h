#pragma once
// Irradiance per pixel from the eight probes around its surface: trilinear weights, SH evaluated
// at the normal, negative results clamped. Kernel: shaders/sh_grid/sh_grid_sample.hlsl.
#include "gi/core/frame_context.h"
#include "gi/deferred/gbuffer_pass.h"
#include "gi/sh_grid/sh_grid_resources.h"

namespace lumina::gi {

class ShGridSamplePass {
public:
    static constexpr const char* kName = "sh grid: sample";
    void record(FrameContext& frame, const ShGridResources& r, const GBuffer& gbuffer) const;
};

} // namespace lumina::gi
