#include "gi/screen_probes/probe_trace_far_field_pass.h"

#include "gi/screen_probes/probe_trace_bindings.h"

namespace lumina::gi {

void ProbeTraceFarFieldPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    probeTracePass(frame, kName, "screen_probes/probe_trace_far_field", view)
        .read(8, r.nearField)
        .write(0, r.hits)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
