#pragma once
// This update's rays into every active probe's octahedral irradiance, with hysteresis; borders copied.
// Kernel: shaders/ddgi/ddgi_blend_irradiance.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"

namespace lumina::gi {

class DdgiBlendIrradiancePass {
public:
    static constexpr const char* kName = "ddgi: blend irradiance";
    void record(FrameContext& frame, const DdgiResources& r) const;
};

} // namespace lumina::gi
