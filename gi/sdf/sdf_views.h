#pragma once
// Looking at a scene's SDFs: camera views traced through them on the GPU (normals, and the
// kernel behind the trace throughput benchmark), the global SDF read back from the GPU, and
// a colour-mapped slice of it. Used by `lumina sdf`, the golden tests and the GPU tests.
#include "gi/core/frame_context.h"
#include "gi/image/image.h"
#include "gi/scene/scene.h"
#include "gi/sdf/global_sdf.h"
#include "gi/sdf/scene_sdf.h"
#include "rhi/rhi.h"
#include "shaders/sdf/sdf_scene_trace_shared.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace lumina::sdf {

enum class SdfField : uint32_t {
    Near = LUMINA_SDF_TRACE_NEAR_FIELD, // per-mesh SDFs through the instance BVH
    Far = LUMINA_SDF_TRACE_FAR_FIELD,   // the global SDF
    Cone = LUMINA_SDF_TRACE_CONE,       // the global SDF, cone traced
};
const char* fieldName(SdfField field);

// Parameters that suit each field (maxDistance in world units): the shared defaults
// (sdf_scene_shared.h), with more steps for the far field.
gpu::SdfTraceParams defaultTraceParams(SdfField field, float maxDistance);

// One camera ray per pixel through the scene's SDFs (shaders/sdf/sdf_camera_trace.hlsl).
class SdfCameraTracer {
public:
    SdfCameraTracer(rhi::IDevice& device, uint32_t width, uint32_t height);

    // Records the camera upload and the trace as one timed pass named `passName`.
    void record(gi::FrameContext& frame, const SceneSdf& sdfs, const scene::Camera& camera, SdfField field,
                const gpu::SdfTraceParams& params, std::string_view passName, float tanHalfAngle = 0.0f);

    // The last trace's pixels: 0.5 * normal + 0.5 in R, G, B (black on a miss), t in "t".
    image::Image readNormals(rhi::IDevice& device) const;

    // float4 per pixel, row-major: what readNormals reads back.
    const rhi::BufferHandle& pixels() const { return pixels_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    uint32_t width_, height_;
    rhi::BufferHandle view_;
    rhi::BufferHandle pixels_;
};

// One cascade of the global SDF read back in window order (distance, nearest instance:
// kNoInstance where none), with its window's corner and voxel size; cascade 0 of a scene with
// one cascade is the whole scene-fitted grid.
GlobalSdf readGlobalSdf(rhi::IDevice& device, const SceneSdf& sdfs, uint32_t cascade = 0);

// Slice z of a global SDF as a display image, +y up: magma over [-maxDistance, maxDistance]
// (dark inside, bright far outside), white where |distance| is below half a voxel (the
// surfaces), and a darker line every two voxels of distance (the field's level sets).
image::Image globalSdfSliceImage(const GlobalSdf& grid, uint32_t z, float maxDistance);

} // namespace lumina::sdf
