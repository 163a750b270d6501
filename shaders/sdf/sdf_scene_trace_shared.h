#ifndef LUMINA_SDF_SCENE_TRACE_SHARED_H
#define LUMINA_SDF_SCENE_TRACE_SHARED_H
// Push constants of the scene tracing kernels (sdf_trace_rays.hlsl: rays from a buffer;
// sdf_camera_trace.hlsl: one camera ray per pixel), shared with gi/sdf/scene_sdf.cpp, the
// tests and `lumina sdf`.
#include "../common/camera_shared.h"
#include "../common/sdf_scene_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

// Which part of the tracing library a kernel calls.
#define LUMINA_SDF_TRACE_NEAR_FIELD 0u // sdfTraceNearField: per-mesh SDFs through the instance BVH
#define LUMINA_SDF_TRACE_FAR_FIELD 1u  // sdfTraceGlobal: the global SDF
#define LUMINA_SDF_TRACE_CONE 2u       // sdfConeTraceGlobal: the global SDF, cone of tanHalfAngle

struct SdfTraceRaysConstants {
    SdfTraceParams params;
    uint rayCount;
    uint mode;          // LUMINA_SDF_TRACE_*
    float tanHalfAngle; // cone mode only
    uint pad0;
};

struct SdfCameraTraceConstants {
    SdfTraceParams params;
    uint width;
    uint height;
    uint mode;          // LUMINA_SDF_TRACE_*
    float tanHalfAngle; // cone mode only
};

// Constant buffer of sdf_camera_trace.hlsl (a struct around the camera: glslang passes
// members of a ConstantBuffer<T> to functions, not the buffer itself).
struct SdfCameraView {
    GpuCamera camera;
};

LUMINA_STATIC_ASSERT_SIZE(SdfTraceRaysConstants, 32);
LUMINA_STATIC_ASSERT_SIZE(SdfCameraView, 144);
LUMINA_STATIC_ASSERT_SIZE(SdfCameraTraceConstants, 32);

LUMINA_GPU_NAMESPACE_END

#endif
