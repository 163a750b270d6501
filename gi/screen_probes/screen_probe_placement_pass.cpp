#include "gi/screen_probes/screen_probe_placement_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ScreenProbePlacementPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_placement")
        .constantBuffer(1, r.constants)
        .read(0, view.gbuffer.normal)
        .read(1, view.gbuffer.position)
        .write(0, r.probes[view.current])
        .dispatchThreads(r.gridWidth, r.probeRows(), {LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP});
}

} // namespace lumina::gi
