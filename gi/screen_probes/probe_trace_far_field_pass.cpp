#include "gi/screen_probes/probe_trace_far_field_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeTraceFarFieldPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    view.sdf.bindForTracing(frame.compute(kName, "screen_probes/probe_trace_far_field"))
        .constantBuffer(1, r.constants)
        .read(6, r.probes[view.current])
        .read(7, r.rays)
        .write(0, r.hits)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
