#pragma once
// Every probe's rays sphere-traced through the SDFs; hits read the surface cache, misses the sky.
// Kernel: shaders/ddgi/ddgi_trace.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"
#include "gi/frame/gi_scene_representation.h"

namespace lumina::gi {

class DdgiTracePass {
public:
    static constexpr const char* kName = "ddgi: trace";
    void record(FrameContext& frame, const DdgiResources& r, const GiSceneRepresentation& scene) const;
};

} // namespace lumina::gi
