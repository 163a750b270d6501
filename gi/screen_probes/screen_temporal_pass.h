#pragma once
// Pass 12: full-resolution temporal filter with reprojection and disocclusion fallback.
// Kernel: shaders/screen_probes/screen_temporal.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenTemporalPass {
public:
    static constexpr const char* kName = "screen probes: screen temporal";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
