#pragma once
// Pass 2: the cosine-weighted hemisphere around each probe normal, as texel probabilities.
// Kernel: shaders/screen_probes/probe_brdf_pdf.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeBrdfPdfPass {
public:
    static constexpr const char* kName = "screen probes: brdf pdf";
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
