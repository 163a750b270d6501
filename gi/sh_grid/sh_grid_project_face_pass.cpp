#include "gi/sh_grid/sh_grid_project_face_pass.h"

namespace lumina::gi {

void ShGridProjectFacePass::record(FrameContext& frame, const ShGridResources& r,
                                   const rhi::TextureHandle& radiance, const GBuffer& gbuffer,
                                   const gpu::ShGridFaceConstants& face) const {
    frame.compute(kName, "sh_grid/sh_grid_project_face")
        .constantBuffer(0, r.constants)
        .read(0, radiance)
        .read(1, gbuffer.albedo)
        .read(2, gbuffer.normal)
        .read(3, gbuffer.position)
        .read(4, r.bounceSource)
        .write(0, r.partials)
        .constants(face)
        .dispatch(1);
}

} // namespace lumina::gi
