#ifndef LUMINA_CARD_RADIANCE_HLSLI
#define LUMINA_CARD_RADIANCE_HLSLI
// The surface cache's final lighting at a world point on a card: what every SDF-traced gather
// (the screen probes' near field, DDGI's probe rays) reads at a hit. The includer names the
// final layer first:
//
//   Texture2D<float4> gFinalLighting : register(t10); // outgoing radiance; a = 1 where captured
//   #define LUMINA_FINAL_LIGHTING gFinalLighting
//   #include "surface_cache/card_radiance.hlsli"
#include "surface_cache/surface_card_shared.h"

#if !defined(LUMINA_FINAL_LIGHTING)
#error "define LUMINA_FINAL_LIGHTING before including card_radiance.hlsli"
#endif

// Summed coverage below which a card's footprint counts as uncaptured (the caller falls back to
// the voxel lighting).
#define LUMINA_CARD_MIN_COVERAGE 1e-3f

// The final layer around world point p on `card`: bilinear over the four texels around p's
// card-space (u, v), each weighted by its coverage so that uncaptured texels (a = 0, rgb = 0) do
// not darken the surface. The footprint is clamped into the card's rectangle (texel centres from
// x + 0.5 to x + width - 0.5), so a neighbouring card's texels never bleed in; a hit in the
// card's padding reads its edge. rgb: radiance; a: the summed weight of covered texels (0 for a
// card the LOD evicted, so its hits read the voxel lighting).
float4 cardRadiance(SurfaceCard card, float3 p) {
    if (card.atlasRect.z == 0u) {
        return float4(0.0, 0.0, 0.0, 0.0); // evicted by the card LOD: no texels
    }
    const float2 rectMin = float2(card.atlasRect.xy);
    const float2 rectMax = rectMin + float2(card.atlasRect.zw) - 1.0;
    // Texel-centre coordinates: texel i's centre at i.
    const float2 x = clamp(cardToAtlasTexel(card, worldToCardSpace(card, p).xy) - 0.5, rectMin, rectMax);
    const float2 base = floor(x);
    const float2 f = x - base;
    float4 sum = float4(0.0, 0.0, 0.0, 0.0);
    for (uint corner = 0u; corner < 4u; ++corner) {
        const float2 offset = float2(corner & 1u, corner >> 1);
        const float2 w2 = lerp(1.0 - f, f, offset);
        const int2 texel = int2(min(base + offset, rectMax));
        const float4 v = LUMINA_FINAL_LIGHTING.Load(int3(texel, 0));
        const float w = w2.x * w2.y * v.a;
        sum += float4(w * v.rgb, w);
    }
    return sum.a > LUMINA_CARD_MIN_COVERAGE ? float4(sum.rgb / sum.a, sum.a) : float4(0.0, 0.0, 0.0, 0.0);
}

#endif
