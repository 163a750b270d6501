#ifndef LUMINA_SDF_TEST_SHARED_H
#define LUMINA_SDF_TEST_SHARED_H
// Push constants of the SDF test kernel (sdf_trace_test.hlsl), shared with
// tests/sdf/sdf_gpu_test.cpp.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct SdfTraceTestConstants {
    float4 invAtlasDims; // xyz: 1 / atlas texels per axis
    uint rayCount;
    uint volume; // index into the volume table
    uint pad0;
    uint pad1;
};
LUMINA_STATIC_ASSERT_SIZE(SdfTraceTestConstants, 32);

LUMINA_GPU_NAMESPACE_END

#endif
