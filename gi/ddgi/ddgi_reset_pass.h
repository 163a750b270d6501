#pragma once
// Returns the probes of volumes flagged for reset to their lattice points, fresh.
// Kernel: shaders/ddgi/ddgi_reset.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"

namespace lumina::gi {

class DdgiResetPass {
public:
    static constexpr const char* kName = "ddgi: reset probes";
    void record(FrameContext& frame, const DdgiResources& r) const;
};

} // namespace lumina::gi
