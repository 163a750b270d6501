#ifndef LUMINA_CARD_BVH_SHARED_H
#define LUMINA_CARD_BVH_SHARED_H
// GPU layout of the card BVH (gi/surface_cache/card_bvh.h) and the rule that picks the card
// owning a point, shared by the CPU query and card_bvh_traversal.hlsli so both pick alike.
//
// Nodes: a flat array, root at 0, the two children of an interior node side by side (left at
// leftFirst, right at leftFirst + 1). A leaf holds at most four cards, inline in `cards`.
#include "surface_card_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct CardBvhNode {
    float4 minAndLeftFirst; // xyz: bounds min; w: asfloat(leftFirst): interior: left child; leaf: its
                            // first entry in CardBvh::cardOrder (the CPU's list of cards by leaf)
    float4 maxAndCount;     // xyz: bounds max; w: asfloat(card count), 0 for an interior node
    uint4 cards;            // leaf: card indices in lanes [0, count), LUMINA_NO_CARD in the rest
};
LUMINA_STATIC_ASSERT_SIZE(CardBvhNode, 48);

LUMINA_GPU_NAMESPACE_END

#define LUMINA_CARD_BVH_LEAF_SIZE 4u
// Traversal stack entries; a tree of depth d needs d (the builder refuses deeper trees; median
// splits of 4-card leaves reach 32 levels only past 2^33 cards).
#define LUMINA_CARD_BVH_STACK_SIZE 32u
// Lower than any score a containing card can get (scores lie in [-1 - sqrt(3), 5]).
#define LUMINA_CARD_NO_SCORE -1e30f
// The instance of a query that does not know which instance its point lies on (a raster pixel).
#define LUMINA_ANY_INSTANCE 0xffffffffu
// Added to the score of the queried instance's own cards: more than the whole range of
// cardOwnerScore ([-1 - sqrt(3), 1]), so that they outrank every other instance's cards.
#define LUMINA_CARD_OWN_INSTANCE_BONUS 4.0f

LUMINA_GPU_NAMESPACE_BEGIN

LUMINA_INLINE bool pointInBox(float3 p, float3 boxMin, float3 boxMax) {
    return p.x >= boxMin.x && p.y >= boxMin.y && p.z >= boxMin.z && p.x <= boxMax.x && p.y <= boxMax.y &&
           p.z <= boxMax.z;
}

// A card is a candidate owner of p when its padded world bounds contain p (no arithmetic, so
// the CPU and the GPU agree exactly on the candidates).
LUMINA_INLINE bool cardContains(SurfaceCard card, float3 p) {
    return pointInBox(
        p, float3(card.boundsMinAndFlags.x, card.boundsMinAndFlags.y, card.boundsMinAndFlags.z),
        float3(card.boundsMaxAndInstance.x, card.boundsMaxAndInstance.y, card.boundsMaxAndInstance.z));
}

// How well a candidate card fits a point p with surface normal (or reversed ray direction) n,
// unit length: the cosine between card and query normals, less the distance from p to the
// card's unpadded bounds in units of the padding. The cosine picks the card facing the right
// way (the floor's +Y card, not a wall's, at a corner); the distance separates parallel cards
// whose padded bounds overlap (a light quad 0.1 below the ceiling) in favour of the one whose
// surface actually passes through p. One continuous score, so there is no tolerance to tune.
LUMINA_INLINE float cardOwnerScore(SurfaceCard card, float3 p, float3 n) {
    float padding = card.normalAndPadding.w;
    float3 lo = float3(card.boundsMinAndFlags.x, card.boundsMinAndFlags.y, card.boundsMinAndFlags.z) +
                float3(padding, padding, padding);
    float3 hi =
        float3(card.boundsMaxAndInstance.x, card.boundsMaxAndInstance.y, card.boundsMaxAndInstance.z) -
        float3(padding, padding, padding);
    float3 zero = float3(0.0f, 0.0f, 0.0f);
    float3 outside = max(lo - p, zero) + max(p - hi, zero);
    float3 normal = float3(card.normalAndPadding.x, card.normalAndPadding.y, card.normalAndPadding.z);
    return dot(normal, n) - sqrt(dot(outside, outside)) / padding;
}

// Whether a ray travelling along `seenFrom` can see the card's side of its surface: only a side
// that faces it (zero seenFrom: any side, for a query with no ray, or a ray that stopped where it
// started). The owner score alone cannot tell: at a hit within a voxel of an open surface's edge,
// where two zero-thickness walls meet, the unsigned field's gradient points along the wall, the
// score's cosines against the wall's two cards are then small and of either sign, and the sealed
// box's probes read its sky-lit outside (docs/gi.md, energy 41.).
LUMINA_INLINE bool cardFacesRay(SurfaceCard card, float3 seenFrom) {
    float3 normal = float3(card.normalAndPadding.x, card.normalAndPadding.y, card.normalAndPadding.z);
    return dot(normal, seenFrom) <= 0.0f;
}

// cardOwnerScore for a point that an SDF trace found on `instance` (LUMINA_ANY_INSTANCE: not
// known). The trace knows which mesh it hit, and that mesh's cards hold its light: where two
// instances' surfaces coincide (an emissive panel filling a hole in the ceiling, facing the same
// way) the geometric score cannot tell their cards apart, and the lower index, the ceiling's, read
// the dark ceiling for the panel's hits (docs/gi.md, 33.). Another instance's card still owns a
// point that none of the hit instance's cards holds.
LUMINA_INLINE float cardOwnerScoreOnInstance(SurfaceCard card, float3 p, float3 n, uint instance) {
    bool own = instance != LUMINA_ANY_INSTANCE && asuint(card.boundsMaxAndInstance.w) == instance;
    return cardOwnerScore(card, p, n) + (own ? LUMINA_CARD_OWN_INSTANCE_BONUS : 0.0f);
}

LUMINA_GPU_NAMESPACE_END

#endif
