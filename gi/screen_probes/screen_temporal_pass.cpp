#include "gi/screen_probes/screen_temporal_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ScreenTemporalPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/screen_temporal")
        .constantBuffer(1, r.constants)
        .read(0, r.gather)
        .read(1, view.gbuffer.position)
        .read(2, r.screenIrradiance[view.previous()])
        .read(3, r.screenPosition[view.previous()])
        .write(0, r.screenIrradiance[view.current])
        .write(1, r.screenPosition[view.current])
        .dispatchThreads(r.width, r.height, {LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP});
}

} // namespace lumina::gi
