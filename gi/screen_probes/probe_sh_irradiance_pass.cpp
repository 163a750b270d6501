#include "gi/screen_probes/probe_sh_irradiance_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeShIrradiancePass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_sh_irradiance")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.filtered)
        .write(0, r.sh)
        .write(1, r.irradiance)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
