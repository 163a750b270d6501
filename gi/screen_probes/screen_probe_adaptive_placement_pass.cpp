#include "gi/screen_probes/screen_probe_adaptive_placement_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ScreenProbeAdaptivePlacementPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_adaptive_placement")
        .constantBuffer(1, r.constants)
        .read(0, view.gbuffer.normal)
        .read(1, view.gbuffer.position)
        .read(2, r.probes[view.current])
        .write(0, r.adaptiveCandidates)
        .write(1, r.adaptiveRunWanted)
        .dispatch(r.adaptiveRunsPerRow, r.adaptiveHeight); // a group per run of a row's tiles
}

} // namespace lumina::gi
