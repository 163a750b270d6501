#include "gi/screen_probes/probe_composite_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeCompositePass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_composite")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.rays)
        .read(2, r.rayRadiance)
        .write(0, r.frameRadiance)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
