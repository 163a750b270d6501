#ifndef LUMINA_CARD_BVH_TEST_SHARED_H
#define LUMINA_CARD_BVH_TEST_SHARED_H
// Queries and results of the card BVH test kernel (card_bvh_query_test.hlsl), shared with
// tests/surface_cache/card_bvh_gpu_test.cpp.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct CardBvhQuery {
    float4 position; // xyz: world point; w: asfloat(instance), LUMINA_ANY_INSTANCE for none
    float4 normal;   // xyz: unit normal; w: 0
    float4 seenFrom; // xyz: the direction of the ray that found the point, or 0; w: 0
};

struct CardBvhQueryResult {
    float4 ownerAndScore; // x: asfloat(card, LUMINA_NO_CARD for none); y: its score; zw: 0
};

struct CardBvhQueryConstants {
    uint queryCount;
    uint pad0;
    uint pad1;
    uint pad2;
};

LUMINA_STATIC_ASSERT_SIZE(CardBvhQuery, 48);
LUMINA_STATIC_ASSERT_SIZE(CardBvhQueryResult, 16);
LUMINA_STATIC_ASSERT_SIZE(CardBvhQueryConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
