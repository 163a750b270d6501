#include "gi/screen_probes/screen_gather_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ScreenGatherPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/screen_gather")
        .constantBuffer(1, r.constants)
        .read(0, view.gbuffer.normal)
        .read(1, view.gbuffer.position)
        .read(2, r.probes[view.current])
        .read(3, r.irradiance)
        .read(4, r.adaptiveIndex[view.current])
        .sampler(0, r.linearClamp)
        .write(0, r.gather)
        .dispatchThreads(r.width, r.height, {LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP});
}

} // namespace lumina::gi
