#ifndef LUMINA_BVH_TEST_SHARED_H
#define LUMINA_BVH_TEST_SHARED_H
// Push constants of the BVH test kernel (bvh_raycast_test.hlsl), shared with
// tests/bvh/bvh_gpu_test.cpp.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct BvhRaycastConstants {
    uint rayCount;
    uint anyHit; // 1: any-hit query (t = the ray's tMax, prim 0 when something is hit)
    uint pad0;
    uint pad1;
};
LUMINA_STATIC_ASSERT_SIZE(BvhRaycastConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
