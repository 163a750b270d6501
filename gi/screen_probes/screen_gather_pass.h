#pragma once
// Pass 11: full-resolution irradiance from the four nearest probes; sky pixels get none.
// Kernel: shaders/screen_probes/screen_gather.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ScreenGatherPass {
public:
    static constexpr const char* kName = "screen probes: final gather";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
