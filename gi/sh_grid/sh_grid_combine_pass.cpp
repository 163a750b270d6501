#include "gi/sh_grid/sh_grid_combine_pass.h"

#include "shaders/sh_grid/sh_grid_shared.h"

namespace lumina::gi {

void ShGridCombinePass::record(FrameContext& frame, const ShGridResources& r, uint32_t probe) const {
    frame.compute(kName, "sh_grid/sh_grid_combine")
        .read(0, r.partials)
        .write(0, r.coefficients)
        .constants(gpu::ShGridCombineConstants{.probe = probe, .pad0 = 0, .pad1 = 0, .pad2 = 0})
        .dispatch(1);
}

} // namespace lumina::gi
