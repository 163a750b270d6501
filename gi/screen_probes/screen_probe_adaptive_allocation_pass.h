#pragma once
// Pass 1c: the adaptive candidates get the adaptive slots in tile order, their probes and the
// adaptive index. Kernel: shaders/screen_probes/probe_adaptive_allocation.hlsl.
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenProbeAdaptiveAllocationPass {
public:
    static constexpr const char* kName = "screen probes: adaptive allocation";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
