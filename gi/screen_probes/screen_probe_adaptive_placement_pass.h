#pragma once
// Pass 1b: per adaptive tile, the pixel that wants an adaptive probe (one on no uniform probe's
// surface), and per run of a row's tiles how many do. Kernel:
// shaders/screen_probes/probe_adaptive_placement.hlsl.
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenProbeAdaptivePlacementPass {
public:
    static constexpr const char* kName = "screen probes: adaptive placement";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
