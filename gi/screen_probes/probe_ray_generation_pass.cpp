#include "gi/screen_probes/probe_ray_generation_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeRayGenerationPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_ray_generation")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.brdfPdf)
        .read(2, r.lightingPdf)
        .write(0, r.rays)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
