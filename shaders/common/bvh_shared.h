#ifndef LUMINA_BVH_SHARED_H
#define LUMINA_BVH_SHARED_H
// GPU layout of the triangle BVH (gi/bvh/), read by bvh_traversal.hlsli.
//
// Nodes are stored depth-first: an interior node's first child is the next node in the
// array and `index` names its second child; a leaf names its first triangle. Integers
// live in the w lanes as raw bits (asuint/asfloat): loads and bitcasts move bits
// unchanged, so small integers that read as float denormals are never flushed.
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct BvhNode {
    float4 minAndIndex; // xyz: bounds min; w: asfloat(second child) or asfloat(first triangle)
    float4 maxAndCount; // xyz: bounds max; w: asfloat(triangle count), 0 for an interior node
};

// Vertices are stored as they were given (not as v0 + edges): watertight intersection
// needs the shared vertices of neighbouring triangles to be bit-identical.
struct BvhTriangle {
    float4 v0; // w: asfloat(primitive id given at build time)
    float4 v1; // w: 0
    float4 v2; // w: 0
};

// Rays and hits as the test kernel (shaders/bvh/bvh_raycast_test.hlsl) exchanges them.
struct BvhRay {
    float4 originAndTMin;
    float4 directionAndTMax;
};

struct BvhRayHit {
    float4 tuvAndPrim; // x: t (the ray's tMax on a miss); y, z: barycentric weights of v1 and v2;
                       // w: asfloat(primitive id), asfloat(LUMINA_BVH_NO_HIT) on a miss
};

LUMINA_STATIC_ASSERT_SIZE(BvhNode, 32);
LUMINA_STATIC_ASSERT_SIZE(BvhTriangle, 48);
LUMINA_STATIC_ASSERT_SIZE(BvhRay, 32);
LUMINA_STATIC_ASSERT_SIZE(BvhRayHit, 16);

LUMINA_GPU_NAMESPACE_END

#define LUMINA_BVH_NO_HIT 0xFFFFFFFFu

#endif
