#include "gi/ddgi/ddgi_reset_pass.h"

#include "gi/ddgi/ddgi_dispatch.h"
#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiResetPass::record(FrameContext& frame, const DdgiResources& r) const {
    frame.compute(kName, "ddgi/ddgi_reset")
        .constantBuffer(1, r.constants)
        .write(0, r.probes)
        .dispatch(ddgiProbeGroups(r));
}

} // namespace lumina::gi
