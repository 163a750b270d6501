#include "gi/ddgi/ddgi_sample_pass.h"

#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiSamplePass::record(FrameContext& frame, const DdgiResources& r, const GBuffer& gbuffer) const {
    frame.compute(kName, "ddgi/ddgi_sample")
        .constantBuffer(1, r.constants)
        .read(0, gbuffer.normal)
        .read(1, gbuffer.position)
        .read(2, r.probes)
        .read(3, r.irradiance)
        .read(4, r.distance)
        .sampler(0, r.linearClamp)
        .write(0, r.sampled)
        .dispatchThreads(r.width, r.height, {LUMINA_DDGI_SAMPLE_GROUP, LUMINA_DDGI_SAMPLE_GROUP});
}

} // namespace lumina::gi
