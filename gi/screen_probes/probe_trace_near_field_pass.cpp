#include "gi/screen_probes/probe_trace_near_field_pass.h"

#include "gi/screen_probes/probe_trace_bindings.h"

namespace lumina::gi {

void ProbeTraceNearFieldPass::record(FrameContext& frame, const ScreenProbeView& view) const {
    const ScreenProbeResources& r = view.resources;
    const SurfaceCacheView& cache = *view.surfaceCache;
    probeTracePass(frame, kName, "screen_probes/probe_trace_near_field", view)
        .write(0, r.hits)
        .write(1, r.nearField)
        .read(8, cache.cardBvh)
        .read(9, cache.cards)
        .read(10, cache.finalLighting)
        .read(11, cache.voxelLighting)
        .dispatch(view.groupsX(), view.groupsY());
}

} // namespace lumina::gi
