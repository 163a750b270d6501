#pragma once
// Probes inside or too near geometry move within their cell (from the fixed rays and the global SDF).
// Kernel: shaders/ddgi/ddgi_relocate.hlsl (its header says how).
#include "gi/core/frame_context.h"
#include "gi/ddgi/ddgi_resources.h"
#include "gi/sdf/scene_sdf.h"

namespace lumina::gi {

class DdgiRelocatePass {
public:
    static constexpr const char* kName = "ddgi: relocate probes";
    void record(FrameContext& frame, const DdgiResources& r, const sdf::SceneSdf& sdf) const;
};

} // namespace lumina::gi
