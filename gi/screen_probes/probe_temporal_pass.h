#pragma once
// Pass 8: exponential accumulation of probe radiance, outlier clamp, disocclusion, NaN-free history.
// Kernel: shaders/screen_probes/probe_temporal.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeTemporalPass {
public:
    static constexpr const char* kName = "screen probes: temporal";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
