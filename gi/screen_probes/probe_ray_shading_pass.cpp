#include "gi/screen_probes/probe_ray_shading_pass.h"

#include "shaders/screen_probes/screen_probe_shared.h"

namespace lumina::gi {

void ProbeRayShadingPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    frame.compute(kName, "screen_probes/probe_ray_shading")
        .constantBuffer(1, r.constants)
        .read(0, r.probes[view.current])
        .read(1, r.hits)
        .read(2, view.voxelLighting)
        .read(3, r.nearField)
        .read(4, r.rays)
        .read(5, view.sky)
        .sampler(0, r.linearClamp)
        .write(0, r.rayRadiance)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
