#ifndef LUMINA_CARD_BVH_TRAVERSAL_HLSLI
#define LUMINA_CARD_BVH_TRAVERSAL_HLSLI
// Finds the card that owns a point (an SDF hit): the GPU twin of findCardOwner in
// gi/surface_cache/card_bvh.cpp. Visits every node whose box holds the point (a point query
// cannot stop early: a later card may fit better), scores each containing card with
// cardOwnerScoreOnInstance (card_bvh_shared.h) and keeps the highest (among the cards that face
// the ray, cardFacesRay); equal scores go to the
// lower index.
//
// The includer says where nodes and cards come from:
//
//   StructuredBuffer<CardBvhNode> gCardBvh : register(t0);
//   StructuredBuffer<SurfaceCard> gCards : register(t1);
//   #define LUMINA_CARD_BVH_NODE(i) gCardBvh[i]
//   #define LUMINA_SURFACE_CARD(i) gCards[i]
//   #include "surface_cache/card_bvh_traversal.hlsli"
#include "card_bvh_shared.h"

#if !defined(LUMINA_CARD_BVH_NODE) || !defined(LUMINA_SURFACE_CARD)
#error "define LUMINA_CARD_BVH_NODE(i) and LUMINA_SURFACE_CARD(i) before including card_bvh_traversal.hlsli"
#endif

struct CardOwner {
    uint card;   // LUMINA_NO_CARD when no card's bounds hold the point
    float score; // cardOwnerScore of that card, LUMINA_CARD_NO_SCORE when none
};

// p: world position; n: unit surface normal at p (or the reversed ray direction); instance: the
// scene instance an SDF hit names (SdfHit.ids.x), whose cards come first, or LUMINA_ANY_INSTANCE;
// seenFrom: the direction of the ray that found p (sdfSeenFrom), whose back-facing cards are
// skipped (cardFacesRay), or zero.
CardOwner findCardOwner(float3 p, float3 n, uint instance, float3 seenFrom) {
    CardOwner best;
    best.card = LUMINA_NO_CARD;
    best.score = LUMINA_CARD_NO_SCORE;
    uint stack[LUMINA_CARD_BVH_STACK_SIZE];
    uint stackSize = 1u;
    stack[0] = 0u;
    while (stackSize > 0u) {
        stackSize -= 1u;
        CardBvhNode node = LUMINA_CARD_BVH_NODE(stack[stackSize]);
        if (!pointInBox(p, node.minAndLeftFirst.xyz, node.maxAndCount.xyz)) {
            continue;
        }
        uint count = asuint(node.maxAndCount.w);
        if (count == 0u) {
            // Both children or neither: the host refuses trees deeper than the stack.
            if (stackSize + 2u <= LUMINA_CARD_BVH_STACK_SIZE) {
                uint left = asuint(node.minAndLeftFirst.w);
                stack[stackSize] = left + 1u;
                stack[stackSize + 1u] = left;
                stackSize += 2u;
            }
            continue;
        }
        for (uint i = 0u; i < count; ++i) {
            uint index = node.cards[i];
            SurfaceCard card = LUMINA_SURFACE_CARD(index);
            if (!cardContains(card, p) || !cardFacesRay(card, seenFrom)) {
                continue;
            }
            float score = cardOwnerScoreOnInstance(card, p, n, instance);
            if (score > best.score || (score == best.score && index < best.card)) {
                best.card = index;
                best.score = score;
            }
        }
    }
    return best;
}

#endif
