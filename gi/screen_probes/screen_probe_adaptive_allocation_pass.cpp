#include "gi/screen_probes/screen_probe_adaptive_allocation_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ScreenProbeAdaptiveAllocationPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_adaptive_allocation")
        .constantBuffer(1, r.constants)
        .read(0, view.gbuffer.normal)
        .read(1, view.gbuffer.position)
        .read(2, r.adaptiveCandidates)
        .read(3, r.adaptiveRunWanted)
        .write(0, r.probes[view.current])
        .write(1, r.adaptiveIndex[view.current])
        .write(2, r.adaptiveWanted)
        .dispatch(r.adaptiveHeight); // one group per row of tiles
}

} // namespace lumina::gi
