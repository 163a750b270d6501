#include "gi/screen_probes/probe_lighting_pdf_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeLightingPdfPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_lighting_pdf")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.probes[view.previous()])
        .read(2, r.history[view.previous()])
        .read(3, r.adaptiveIndex[view.previous()])
        .write(0, r.lightingPdf)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
