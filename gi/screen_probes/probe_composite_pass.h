#pragma once
// Pass 7: rays into each probe's 8x8 radiance map, MIS-weighted.
// Kernel: shaders/screen_probes/probe_composite.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeCompositePass {
public:
    static constexpr const char* kName = "screen probes: composite";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
