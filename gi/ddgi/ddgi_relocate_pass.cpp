#include "gi/ddgi/ddgi_relocate_pass.h"

#include "gi/ddgi/ddgi_dispatch.h"
#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiRelocatePass::record(FrameContext& frame, const DdgiResources& r, const sdf::SceneSdf& sdf) const {
    ComputePass pass = frame.compute(kName, "ddgi/ddgi_relocate");
    sdf.bindForTracing(pass)
        .constantBuffer(1, r.constants)
        .read(6, r.rayData)
        .write(0, r.probes)
        .dispatch(ddgiProbeGroups(r));
}

} // namespace lumina::gi
