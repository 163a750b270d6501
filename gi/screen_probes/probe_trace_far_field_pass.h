#pragma once
// Pass 6: cone traces through the global SDF, one hit record per ray (after the near field: for
// the rays it missed, from the near-field distance on).
// Kernel: shaders/screen_probes/probe_trace_far_field.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeTraceFarFieldPass {
public:
    static constexpr const char* kName = "screen probes: trace far field";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
