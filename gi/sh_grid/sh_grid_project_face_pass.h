#pragma once
// One cube face of a probe projected onto the nine SH basis functions (radiance, not yet
// convolved), into its slot of ShGridResources::partials. Kernel:
// shaders/sh_grid/sh_grid_project_face.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/deferred/gbuffer_pass.h"
#include "gi/sh_grid/sh_grid_resources.h"
#include "shaders/sh_grid/sh_grid_shared.h"

namespace lumina::gi {

class ShGridProjectFacePass {
public:
    static constexpr const char* kName = "sh grid: project";
    // `radiance`: the face's linear radiance (faceSize^2); `gbuffer`: what the face sees, read
    // when face.bounce is set.
    void record(FrameContext& frame, const ShGridResources& r, const rhi::TextureHandle& radiance,
                const GBuffer& gbuffer, const gpu::ShGridFaceConstants& face) const;
};

} // namespace lumina::gi
