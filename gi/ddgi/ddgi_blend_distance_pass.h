#pragma once
// This update's hit distances into every active probe's octahedral mean distance and its square; borders
// copied. Kernel: shaders/ddgi/ddgi_blend_distance.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"

namespace lumina::gi {

class DdgiBlendDistancePass {
public:
    static constexpr const char* kName = "ddgi: blend distance";
    void record(FrameContext& frame, const DdgiResources& r) const;
};

} // namespace lumina::gi
