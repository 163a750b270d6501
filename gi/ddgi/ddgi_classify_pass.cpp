#include "gi/ddgi/ddgi_classify_pass.h"

#include "gi/ddgi/ddgi_dispatch.h"
#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

void DdgiClassifyPass::record(FrameContext& frame, const DdgiResources& r) const {
    frame.compute(kName, "ddgi/ddgi_classify")
        .constantBuffer(1, r.constants)
        .read(6, r.rayData)
        .write(0, r.probes)
        .dispatch(ddgiProbeGroups(r));
}

} // namespace lumina::gi
