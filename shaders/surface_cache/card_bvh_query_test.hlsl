// lumina-kernel: cs main
// Test kernel for the card BVH (tests/surface_cache/card_bvh_gpu_test.cpp): one thread per
// query, the owning card and its score written out for comparison with the CPU.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "surface_cache/card_bvh_shared.h"
#include "surface_cache/card_bvh_test_shared.h"
#include "surface_cache/surface_card_shared.h"

LUMINA_PUSH_CONSTANTS(CardBvhQueryConstants, gConstants);

StructuredBuffer<CardBvhNode> gCardBvh : register(t0);
StructuredBuffer<SurfaceCard> gCards : register(t1);
StructuredBuffer<CardBvhQuery> gQueries : register(t2);
RWStructuredBuffer<CardBvhQueryResult> gResults : register(u0);

#define LUMINA_CARD_BVH_NODE(i) gCardBvh[i]
#define LUMINA_SURFACE_CARD(i) gCards[i]
#include "surface_cache/card_bvh_traversal.hlsli"

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id
                                 : SV_DispatchThreadID) {
    if (id.x >= gConstants.queryCount) {
        return;
    }
    CardBvhQuery query = gQueries[id.x];
    CardOwner owner =
        findCardOwner(query.position.xyz, query.normal.xyz, asuint(query.position.w), query.seenFrom.xyz);
    CardBvhQueryResult result;
    result.ownerAndScore = float4(asfloat(owner.card), owner.score, 0.0f, 0.0f);
    gResults[id.x] = result;
}
