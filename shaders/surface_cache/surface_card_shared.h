#ifndef LUMINA_SURFACE_CARD_SHARED_H
#define LUMINA_SURFACE_CARD_SHARED_H
// GPU layout of a surface-cache card (gi/surface_cache/, docs/surface_cache.md): one card per
// instance and card of its mesh, placed in world space.
//
// Card space: worldToCard maps a world point to (u, v, z). u and v run 0..1 across the card's
// atlas rectangle (u along the rectangle's width, v along its height); z runs 0..1 through the
// card's depth range, 0 at the front (the capture plane, farthest along the normal) and 1 at the
// back. A capture camera at z = 0 looking along -normal sees what the card holds; u x v points
// along the normal, so the capture is not mirrored. Integers live in w lanes as raw bits.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct SurfaceCard {
    float4 worldToCard0;         // rows of the affine world-to-card map: card = row . (world, 1)
    float4 worldToCard1;         //
    float4 worldToCard2;         //
    float4 boundsMinAndFlags;    // xyz: world bounds min, padded; w: asfloat(LUMINA_CARD_* flags)
    float4 boundsMaxAndInstance; // xyz: world bounds max, padded; w: asfloat(instance index)
    float4 normalAndPadding;     // xyz: unit world normal; w: the padding added to the bounds (world)
    uint4 atlasRect;             // texels: x, y, width, height (whole tiles); zero when evicted
    uint4 lightMask;             // bit i (lane i / 32, bit i % 32): scene light i can reach the card
    uint4 info; // x: mesh, y: card of the mesh, z: axis (LUMINA_CARD_AXIS_*), w: last capture frame
};
LUMINA_STATIC_ASSERT_SIZE(SurfaceCard, 144);

LUMINA_GPU_NAMESPACE_END

// Flags. VISIBLE: the card holds atlas texels (cleared while the LOD evicts it: no texels, hits
// on it read the voxel lighting). DIRTY: its
// atlas texels are stale and must be captured again. STATIC / DYNAMIC: its instance has never /
// has moved since load. TWO_SIDED: it holds back faces of a double-sided material.
#define LUMINA_CARD_VISIBLE 1u
#define LUMINA_CARD_DIRTY 2u
#define LUMINA_CARD_STATIC 4u
#define LUMINA_CARD_DYNAMIC 8u
#define LUMINA_CARD_TWO_SIDED 16u

// Mesh-space axis a card looks along (its normal before the instance transform): 2 * axis + (negative ? 1 :
// 0).
#define LUMINA_CARD_AXIS_POS_X 0u
#define LUMINA_CARD_AXIS_NEG_X 1u
#define LUMINA_CARD_AXIS_POS_Y 2u
#define LUMINA_CARD_AXIS_NEG_Y 3u
#define LUMINA_CARD_AXIS_POS_Z 4u
#define LUMINA_CARD_AXIS_NEG_Z 5u

#define LUMINA_NO_CARD 0xFFFFFFFFu
#define LUMINA_CARD_LIGHT_MASK_BITS 128u

LUMINA_GPU_NAMESPACE_BEGIN

// (u, v, z) of a world point in the card's space (see above).
LUMINA_INLINE float3 worldToCardSpace(SurfaceCard card, float3 world) {
    float4 p = float4(world.x, world.y, world.z, 1.0f);
    return float3(dot(card.worldToCard0, p), dot(card.worldToCard1, p), dot(card.worldToCard2, p));
}

// Atlas texel coordinates (not normalised) of card-space (u, v).
LUMINA_INLINE float2 cardToAtlasTexel(SurfaceCard card, float2 uv) {
    return float2(float(card.atlasRect.x) + uv.x * float(card.atlasRect.z),
                  float(card.atlasRect.y) + uv.y * float(card.atlasRect.w));
}

LUMINA_GPU_NAMESPACE_END

#endif
