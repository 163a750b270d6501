// lumina-kernel: cs screen
// lumina-kernel: cs atlas
// The viewer's card outlines (app/viewer/gi_views.cpp): which surface-cache card covers which
// surface, drawn from the cards the surface cache holds on the GPU this frame.
//   screen: the final image, each pixel tinted by the card that owns its GBuffer surface (the
//           card BVH lookup that SDF hits use, findCardOwner), an outline where the owner
//           changes between neighbouring pixels, and a red tint on surfaces no card holds.
//   atlas:  an atlas layer, each card's rectangle (its tiles, from the tile-to-card lookup)
//           tinted by the card and outlined.
#include "viewer/visualise_common.hlsli"
#include "surface_cache/card_bvh_shared.h"
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"

Texture2D<float4> gImage : register(t0);    // screen: the composite's display image; atlas: the layer
Texture2D<float4> gPosition : register(t1); // GBuffer world position; w: view depth, 0 off surfaces
Texture2D<float4> gNormal : register(t2);   // GBuffer unit world normal
StructuredBuffer<CardBvhNode> gCardBvh : register(t3);
StructuredBuffer<SurfaceCard> gCards : register(t4);
Texture2D<uint> gTileOwner : register(t5); // one texel per atlas tile: its card, LUMINA_NO_CARD where free

#define LUMINA_CARD_BVH_NODE(i) gCardBvh[i]
#define LUMINA_SURFACE_CARD(i) gCards[i]
#include "surface_cache/card_bvh_traversal.hlsli"

// How much of a card's colour covers its texels, and of red the surfaces without a card.
#define LUMINA_CARD_TINT 0.3
#define LUMINA_NO_CARD_TINT 0.6
// Atlas outlines are this many output texels per 512 of the atlas's side, so that they stay
// visible when a large atlas is shrunk to fit the window.
#define LUMINA_ATLAS_OUTLINE_PER_512 1u

// The card owning the surface seen through pixel p; LUMINA_NO_CARD off surfaces or where no
// card's bounds hold it; ~1u - 1 (a second sentinel) off the image.
#define LUMINA_OFF_IMAGE 0xFFFFFFFEu
uint pixelCard(int2 p) {
    if (any(p < 0) || any(p >= int2(gVisualise.size))) {
        return LUMINA_OFF_IMAGE;
    }
    const float4 position = gPosition.Load(int3(p, 0));
    if (position.w <= 0.0) {
        return LUMINA_NO_CARD;
    }
    const float3 n = normalize(gNormal.Load(int3(p, 0)).xyz);
    return findCardOwner(position.xyz, n, LUMINA_ANY_INSTANCE, float3(0.0, 0.0, 0.0)).card;
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void screen(uint3 id : SV_DispatchThreadID) {
    if (outside(id.xy)) {
        return;
    }
    const int2 p = int2(id.xy);
    const float3 image = gImage.Load(int3(p, 0)).rgb;
    const uint card = pixelCard(p);
    float3 color = image;
    if (card == LUMINA_NO_CARD) {
        const bool surface = gPosition.Load(int3(p, 0)).w > 0.0;
        color = surface ? lerp(image, float3(1.0, 0.0, 0.0), LUMINA_NO_CARD_TINT) : image;
    } else {
        color = lerp(image, idColor(card), LUMINA_CARD_TINT);
        const uint right = pixelCard(p + int2(1, 0));
        const uint below = pixelCard(p + int2(0, 1));
        if ((right != card && right != LUMINA_OFF_IMAGE) || (below != card && below != LUMINA_OFF_IMAGE)) {
            color = idColor(card);
        }
    }
    gOutput[id.xy] = float4(color, 1.0);
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void atlas(uint3 id : SV_DispatchThreadID) {
    if (outside(id.xy)) {
        return;
    }
    const float3 layer = display(gImage.Load(int3(id.xy, 0)));
    const uint card = gTileOwner.Load(int3(id.xy / LUMINA_ATLAS_TILE_SIZE, 0));
    float3 color = layer;
    if (card != LUMINA_NO_CARD) {
        const uint4 rect = gCards[card].atlasRect;
        const uint width = max(1u, gVisualise.size.x / 512u * LUMINA_ATLAS_OUTLINE_PER_512);
        const uint2 local = id.xy - rect.xy;
        const bool edge = any(local < width) || any(local + width >= rect.zw);
        color = edge ? idColor(card) : lerp(layer, idColor(card), LUMINA_CARD_TINT);
    }
    gOutput[id.xy] = float4(color, 1.0);
}
