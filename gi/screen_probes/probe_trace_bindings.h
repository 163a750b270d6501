#pragma once
// The bindings the near-field and far-field traces share
// (shaders/screen_probes/probe_trace_common.hlsli): the SDF scene (b0, t0-t5, s0), the constants
// (b1), this frame's probes (t6) and the rays (t7). Each pass adds its own from t8 on.
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

#include <string_view>

namespace lumina::gi {

inline ComputePass probeTracePass(FrameContext& frame, std::string_view name, std::string_view kernel,
                                  const ScreenProbeView& view) {
    ComputePass pass = frame.compute(name, kernel);
    view.sdf.bindForTracing(pass)
        .constantBuffer(1, view.resources.constants)
        .read(6, view.resources.probes[view.current])
        .read(7, view.resources.rays);
    return pass;
}

} // namespace lumina::gi
