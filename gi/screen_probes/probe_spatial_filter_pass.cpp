#include "gi/screen_probes/probe_spatial_filter_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeSpatialFilterPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_spatial_filter")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.history[view.current])
        .read(2, r.probeAge[view.current])
        .write(0, r.filtered)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
