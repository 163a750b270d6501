#pragma once
// Pass 5: sphere traces through the mesh SDFs up to the near-field distance; hits read the
// surface cache's final lighting through the card BVH (the voxel lighting where no card covers
// them). Writes the hit records and the near-field radiance per ray; the far field then traces
// only the misses, from the near-field distance on.
// Kernel: shaders/screen_probes/probe_trace_near_field.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/screen_probes/screen_probe_view.h"

namespace lumina::gi {

class ProbeTraceNearFieldPass {
public:
    static constexpr const char* kName = "screen probes: trace near field";
    // view.surfaceCache must be set.
    void record(FrameContext& frame, const ScreenProbeView& view) const;
};

} // namespace lumina::gi
