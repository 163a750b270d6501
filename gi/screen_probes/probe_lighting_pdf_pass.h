#pragma once
// Pass 3: texel probabilities from last frame's probe radiance, reprojected; a floor keeps every direction
// reachable. Kernel: shaders/screen_probes/probe_lighting_pdf.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeLightingPdfPass {
public:
    static constexpr const char* kName = "screen probes: lighting pdf";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
