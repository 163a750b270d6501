#pragma once
// Irradiance per pixel from the eight probes around its surface: trilinear x wrap shading x Chebyshev
// visibility. Kernel: shaders/ddgi/ddgi_sample.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"
#include "gi/deferred/gbuffer_pass.h"

namespace lumina::gi {

class DdgiSamplePass {
public:
    static constexpr const char* kName = "ddgi: sample";
    void record(FrameContext& frame, const DdgiResources& r, const GBuffer& gbuffer) const;
};

} // namespace lumina::gi
