#pragma once
// Pass 10: L2 SH of each probe's radiance, irradiance into bordered octahedral tiles.
// Kernel: shaders/screen_probes/probe_sh_irradiance.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeShIrradiancePass {
public:
    static constexpr const char* kName = "screen probes: sh irradiance";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
