#pragma once
// A probe's irradiance coefficients from its six face projections: summed, then convolved with
// the clamped cosine analytically. Kernel: shaders/sh_grid/sh_grid_combine.hlsl.
#include "gi/core/frame_context.h"
#include "gi/sh_grid/sh_grid_resources.h"

namespace lumina::gi {

class ShGridCombinePass {
public:
    static constexpr const char* kName = "sh grid: combine";
    void record(FrameContext& frame, const ShGridResources& r, uint32_t probe) const;
};

} // namespace lumina::gi
