#pragma once
// Pass 9: cross-bilateral filter over the four grid neighbours (plane distance, normal agreement).
// Kernel: shaders/screen_probes/probe_spatial_filter.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeSpatialFilterPass {
public:
    static constexpr const char* kName = "screen probes: spatial filter";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
