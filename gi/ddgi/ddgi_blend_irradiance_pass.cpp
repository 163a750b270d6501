#include "gi/ddgi/ddgi_blend_irradiance_pass.h"

#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiBlendIrradiancePass::record(FrameContext& frame, const DdgiResources& r) const {
    frame.compute(kName, "ddgi/ddgi_blend_irradiance")
        .constantBuffer(1, r.constants)
        .read(0, r.probes)
        .read(1, r.rayData)
        .write(0, r.irradiance)
        .dispatch(r.layout.probes);
}

} // namespace lumina::gi
