// lumina-kernel: cs main
// Closest hits of a list of rays through the path tracer's scene BVH and surface reader, for
// tests/pathtracer/bvh_brute_force_test.cpp: one thread per ray, writing t, barycentrics and
// the traced triangle, then the surface's front normal and material.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "common/bvh_shared.h"
#include "common/scene_shared.h"
#include "pathtracer/pathtracer_shared.h"

LUMINA_PUSH_CONSTANTS(PtRayQueryConstants, gQuery);

StructuredBuffer<BvhNode> gBvhNodes : register(t0);
StructuredBuffer<BvhTriangle> gBvhTriangles : register(t1);
StructuredBuffer<PtTriangle> gTriangles : register(t2);
StructuredBuffer<GpuVertex> gVertices : register(t3);
StructuredBuffer<uint> gIndices : register(t4);
StructuredBuffer<GpuInstance> gInstances : register(t5);
StructuredBuffer<BvhRay> gRays : register(t6);
RWStructuredBuffer<float4> gHits : register(u0); // two per ray

#define LUMINA_BVH_NODE(i) gBvhNodes[i]
#define LUMINA_BVH_TRIANGLE(i) gBvhTriangles[i]
#include "common/bvh_traversal.hlsli"
#include "pathtracer/surface.hlsli"

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id
                                 : SV_DispatchThreadID) {
    if (id.x >= gQuery.rayCount) {
        return;
    }
    BvhRay ray = gRays[id.x];
    BvhHit hit = bvhTraceClosest(ray.originAndTMin.xyz, ray.directionAndTMax.xyz, ray.originAndTMin.w,
                                 ray.directionAndTMax.w);
    float4 first = float4(hit.t, hit.bary.x, hit.bary.y, asfloat(hit.primId));
    float4 second = float4(0.0f, 0.0f, 0.0f, asfloat(LUMINA_BVH_NO_HIT));
    if (hit.primId != LUMINA_BVH_NO_HIT) {
        PtSurface s = ptLoadSurface(hit.triangleIndex, hit.primId, hit.bary);
        second = float4(s.frontNormal, asfloat(s.material));
    }
    gHits[2u * id.x] = first;
    gHits[2u * id.x + 1u] = second;
}
