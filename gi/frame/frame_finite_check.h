#pragma once
// The finite check (gi/core/finite_check.h) set up for a FrameRenderer: every float texture a pass
// writes is checked anyway; this adds the technique's buffers that hold only float4 values (for
// lumen, the screen probes' ray radiance, near field, frame radiance, radiance history, filtered
// radiance and SH), which a check cannot tell from buffers that mix in integers. The probes' single-float
// unclamped luminance is not among them (the check reads float4s); probe_temporal writes it finite.
#include "gi/core/finite_check.h"
#include "gi/frame/frame_renderer.h"

namespace lumina::gi {

void watchFloatBuffers(FiniteCheck& check, const FrameRenderer& renderer);

} // namespace lumina::gi
