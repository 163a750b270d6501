#pragma once
// Probes with no surface in their cells, or inside geometry, become inactive (not traced beyond their fixed
// rays, not blended). Kernel: shaders/ddgi/ddgi_classify.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"

namespace lumina::gi {

class DdgiClassifyPass {
public:
    static constexpr const char* kName = "ddgi: classify probes";
    void record(FrameContext& frame, const DdgiResources& r) const;
};

} // namespace lumina::gi
