#pragma once
// Pass 4: jittered low-discrepancy rays from both PDFs, each with its balance-heuristic weight.
// Kernel: shaders/screen_probes/probe_ray_generation.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeRayGenerationPass {
public:
    static constexpr const char* kName = "screen probes: mis directions";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
