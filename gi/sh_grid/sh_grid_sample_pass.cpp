#include "gi/sh_grid/sh_grid_sample_pass.h"

#include "shaders/sh_grid/sh_grid_shared.h"

namespace lumina::gi {

void ShGridSamplePass::record(FrameContext& frame, const ShGridResources& r, const GBuffer& gbuffer) const {
    frame.compute(kName, "sh_grid/sh_grid_sample")
        .constantBuffer(0, r.constants)
        .read(0, gbuffer.normal)
        .read(1, gbuffer.position)
        .read(2, r.coefficients)
        .write(0, r.sampled)
        .dispatchThreads(r.width, r.height, {LUMINA_SH_GRID_SAMPLE_GROUP, LUMINA_SH_GRID_SAMPLE_GROUP});
}

} // namespace lumina::gi
