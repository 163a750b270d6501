#ifndef LUMINA_RAY_BOX_HLSLI
#define LUMINA_RAY_BOX_HLSLI
// Conservative ray/box slab test for BVH traversal, shared by C++ and HLSL.
//
// A box may only be culled when the exact ray misses it, or a triangle lying on the box's
// face could be lost. The far distance is therefore widened by 1 + 2*gamma(3) (Ize,
// "Robust BVH Ray Traversal", JCGT 2013; pbrt-v3 section 3.9.2), which covers the rounding
// of (bound - origin) * invDir. A zero direction component gets a huge finite reciprocal
// instead of infinity so that 0 * inf never makes a NaN.
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

// 1 + 2 * gamma(3), gamma(n) = n*eps / (1 - n*eps), eps = 2^-24.
#define LUMINA_RAY_BOX_FAR_SCALE 1.00000036f
// Reciprocal that replaces 1/0 (and 1/denormal): large enough that the slab spans any scene.
#define LUMINA_RAY_BOX_HUGE_RCP 1e30f

LUMINA_INLINE float safeReciprocal(float x) {
    if (abs(x) > 1e-30f) {
        return 1.0f / x;
    }
    return asfloat((asuint(x) & 0x80000000u) | asuint(LUMINA_RAY_BOX_HUGE_RCP));
}

LUMINA_INLINE float3 safeReciprocal3(float3 v) {
    return float3(safeReciprocal(v.x), safeReciprocal(v.y), safeReciprocal(v.z));
}

// Entry and exit distances of the line through the box's slabs (x > y: no overlap).
LUMINA_INLINE float2 boxEntryExit(float3 origin, float3 invDirection, float3 boxMin, float3 boxMax) {
    float3 t0 = (boxMin - origin) * invDirection;
    float3 t1 = (boxMax - origin) * invDirection;
    float3 tNear3 = min(t0, t1);
    float3 tFar3 = max(t0, t1);
    return float2(max(max(tNear3.x, tNear3.y), tNear3.z), min(min(tFar3.x, tFar3.y), tFar3.z));
}

// Returns the entry distance (clamped to tMin) when the ray overlaps [tMin, tMax] inside the
// box, or a negative value (-1) when it does not. tMin must be >= 0.
LUMINA_INLINE float intersectBox(float3 origin, float3 invDirection, float3 boxMin, float3 boxMax, float tMin,
                                 float tMax) {
    float2 range = boxEntryExit(origin, invDirection, boxMin, boxMax);
    float tNear = max(range.x, tMin);
    float tFar = min(range.y * LUMINA_RAY_BOX_FAR_SCALE, tMax);
    return (tNear <= tFar) ? tNear : -1.0f;
}

LUMINA_GPU_NAMESPACE_END

#endif
