#include "gi/screen_probes/probe_brdf_pdf_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeBrdfPdfPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_brdf_pdf")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .write(0, r.brdfPdf)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
