#pragma once
// Pass 1b: adaptive probes where a pixel lies on no uniform probe's surface, one at most per adaptive
// tile, in the slots below the grid. Kernel: shaders/screen_probes/probe_adaptive_placement.hlsl.
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenProbeAdaptivePlacementPass {
public:
    static constexpr const char* kName = "screen probes: adaptive placement";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
