#ifndef LUMINA_BVH_TRAVERSAL_HLSLI
#define LUMINA_BVH_TRAVERSAL_HLSLI
// Stack-based traversal of the triangle BVH (layout: bvh_shared.h; built by gi/bvh/), the
// GPU twin of gi/bvh/bvh_query.cpp: same watertight triangle test, same conservative box
// test, same order (nearer child first, farther pushed with its entry distance).
//
// The includer says where nodes and triangles come from before including this file, so
// that one kernel may hold several BVHs or offset into a shared buffer:
//
//   StructuredBuffer<BvhNode> gBvhNodes : register(t0);
//   StructuredBuffer<BvhTriangle> gBvhTriangles : register(t1);
//   #define LUMINA_BVH_NODE(i) gBvhNodes[i]
//   #define LUMINA_BVH_TRIANGLE(i) gBvhTriangles[i]
//   #include "common/bvh_traversal.hlsli"
//
// The stack holds LUMINA_BVH_STACK_SIZE entries, enough for trees of depth up to one more
// than that (the host checks Bvh::depth); deeper trees would drop subtrees, never overrun.
#include "bvh_shared.h"
#include "ray_box.hlsli"
#include "ray_triangle.hlsli"

#if !defined(LUMINA_BVH_NODE) || !defined(LUMINA_BVH_TRIANGLE)
#error "define LUMINA_BVH_NODE(i) and LUMINA_BVH_TRIANGLE(i) before including bvh_traversal.hlsli"
#endif

#ifndef LUMINA_BVH_STACK_SIZE
#define LUMINA_BVH_STACK_SIZE 64
#endif

struct BvhHit {
    float t;            // the ray's tMax on a miss
    float2 bary;        // weights of v1 and v2
    uint primId;        // LUMINA_BVH_NO_HIT on a miss
    uint triangleIndex; // index into the triangle buffer, LUMINA_BVH_NO_HIT on a miss
};

float bvhNodeEntry(uint node, float3 origin, float3 invDir, float tMin, float tMax) {
    BvhNode n = LUMINA_BVH_NODE(node);
    return intersectBox(origin, invDir, n.minAndIndex.xyz, n.maxAndCount.xyz, tMin, tMax);
}

// anyHit: return at the first hit found instead of the nearest.
BvhHit bvhTrace(float3 origin, float3 direction, float tMin, float tMax, bool anyHit) {
    BvhHit hit;
    hit.t = tMax;
    hit.bary = float2(0.0f, 0.0f);
    hit.primId = LUMINA_BVH_NO_HIT;
    hit.triangleIndex = LUMINA_BVH_NO_HIT;

    WatertightRay wray = makeWatertightRay(origin, direction);
    float3 invDir = safeReciprocal3(direction);
    float rootEntry = bvhNodeEntry(0u, origin, invDir, tMin, tMax);
    if (rootEntry < 0.0f) {
        return hit;
    }
    uint stackNode[LUMINA_BVH_STACK_SIZE];
    float stackEntry[LUMINA_BVH_STACK_SIZE];
    uint stackSize = 1u;
    stackNode[0] = 0u;
    stackEntry[0] = rootEntry;
    while (stackSize > 0u) {
        stackSize -= 1u;
        uint node = stackNode[stackSize];
        if (stackEntry[stackSize] > hit.t) {
            continue; // a nearer hit was found after this node was pushed
        }
        for (;;) {
            BvhNode n = LUMINA_BVH_NODE(node);
            uint count = asuint(n.maxAndCount.w);
            uint index = asuint(n.minAndIndex.w);
            if (count != 0u) {
                for (uint i = index; i < index + count; ++i) {
                    BvhTriangle tri = LUMINA_BVH_TRIANGLE(i);
                    float t;
                    float2 bary;
                    if (intersectTriangleWatertight(wray, tri.v0.xyz, tri.v1.xyz, tri.v2.xyz, tMin, hit.t, t,
                                                    bary)) {
                        hit.t = t;
                        hit.bary = bary;
                        hit.primId = asuint(tri.v0.w);
                        hit.triangleIndex = i;
                        if (anyHit) {
                            return hit;
                        }
                    }
                }
                break;
            }
            uint left = node + 1u;
            uint right = index;
            float tLeft = bvhNodeEntry(left, origin, invDir, tMin, hit.t);
            float tRight = bvhNodeEntry(right, origin, invDir, tMin, hit.t);
            if (tLeft >= 0.0f && tRight >= 0.0f) {
                bool leftFirst = tLeft <= tRight;
                if (stackSize < LUMINA_BVH_STACK_SIZE) {
                    stackNode[stackSize] = leftFirst ? right : left;
                    stackEntry[stackSize] = leftFirst ? tRight : tLeft;
                    stackSize += 1u;
                }
                node = leftFirst ? left : right;
            } else if (tLeft >= 0.0f) {
                node = left;
            } else if (tRight >= 0.0f) {
                node = right;
            } else {
                break;
            }
        }
    }
    return hit;
}

BvhHit bvhTraceClosest(float3 origin, float3 direction, float tMin, float tMax) {
    return bvhTrace(origin, direction, tMin, tMax, false);
}

bool bvhTraceAny(float3 origin, float3 direction, float tMin, float tMax) {
    return bvhTrace(origin, direction, tMin, tMax, true).primId != LUMINA_BVH_NO_HIT;
}

#endif
