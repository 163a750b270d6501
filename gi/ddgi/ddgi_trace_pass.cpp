#include "gi/ddgi/ddgi_trace_pass.h"

#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiTracePass::record(FrameContext& frame, const DdgiResources& r,
                           const GiSceneRepresentation& scene) const {
    const SurfaceCacheView cache = scene.surfaceCacheView();
    ComputePass pass = frame.compute(kName, "ddgi/ddgi_trace");
    scene.sdf()
        .bindForTracing(pass)
        .constantBuffer(1, r.constants)
        .read(6, r.probes)
        .read(7, cache.cardBvh)
        .read(8, cache.cards)
        .read(9, cache.finalLighting)
        .read(10, cache.voxelLighting)
        .read(11, scene.sky())
        .write(0, r.rayData)
        .dispatch(r.layout.probes);
}

} // namespace lumina::gi
