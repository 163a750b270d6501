// lumina-kernel: cs main
// Test kernel for the GPU BVH traversal (tests/bvh/bvh_gpu_test.cpp): one thread per ray,
// closest or any hit, written out as BvhRayHit for comparison with the CPU traversal.
#include "bvh/bvh_test_shared.h"
#include "common/bindings.hlsli"
#include "common/bvh_shared.h"
#include "common/constants_shared.h"

LUMINA_PUSH_CONSTANTS(BvhRaycastConstants, gConstants);

StructuredBuffer<BvhNode> gBvhNodes : register(t0);
StructuredBuffer<BvhTriangle> gBvhTriangles : register(t1);
StructuredBuffer<BvhRay> gRays : register(t2);
RWStructuredBuffer<BvhRayHit> gHits : register(u0);

#define LUMINA_BVH_NODE(i) gBvhNodes[i]
#define LUMINA_BVH_TRIANGLE(i) gBvhTriangles[i]
#include "common/bvh_traversal.hlsli"

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id
                                 : SV_DispatchThreadID) {
    if (id.x >= gConstants.rayCount) {
        return;
    }
    BvhRay ray = gRays[id.x];
    float3 origin = ray.originAndTMin.xyz;
    float3 direction = ray.directionAndTMax.xyz;
    float tMin = ray.originAndTMin.w;
    float tMax = ray.directionAndTMax.w;
    BvhRayHit result;
    if (gConstants.anyHit != 0u) {
        bool hit = bvhTraceAny(origin, direction, tMin, tMax);
        result.tuvAndPrim = float4(tMax, 0.0f, 0.0f, asfloat(hit ? 0u : LUMINA_BVH_NO_HIT));
    } else {
        BvhHit hit = bvhTraceClosest(origin, direction, tMin, tMax);
        result.tuvAndPrim = float4(hit.t, hit.bary.x, hit.bary.y, asfloat(hit.primId));
    }
    gHits[id.x] = result;
}
