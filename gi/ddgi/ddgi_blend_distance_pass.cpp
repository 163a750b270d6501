#include "gi/ddgi/ddgi_blend_distance_pass.h"

#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiBlendDistancePass::record(FrameContext& frame, const DdgiResources& r) const {
    frame.compute(kName, "ddgi/ddgi_blend_distance")
        .constantBuffer(1, r.constants)
        .read(0, r.probes)
        .read(1, r.rayData)
        .write(0, r.distance)
        .dispatch(r.layout.probes);
}

} // namespace lumina::gi
