#include "gi/screen_probes/probe_temporal_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeTemporalPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_temporal")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.probes[view.previous()])
        .read(2, r.frameRadiance)
        .read(3, r.history[view.previous()])
        .read(4, r.probeAge[view.previous()])
        .read(5, r.unclamped[view.previous()])
        .read(6, r.adaptiveIndex[view.previous()])
        .write(0, r.history[view.current])
        .write(1, r.probeAge[view.current])
        .write(2, r.unclamped[view.current])
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
