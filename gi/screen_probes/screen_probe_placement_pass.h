#pragma once
// Pass 1: one probe per cell at the GBuffer surface its centre pixel sees; sky probes invalid; the
// adaptive slots emptied for the next pass.
// Kernel: shaders/screen_probes/probe_placement.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenProbePlacementPass {
public:
    static constexpr const char* kName = "screen probes: placement";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
