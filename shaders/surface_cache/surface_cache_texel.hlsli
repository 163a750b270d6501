#ifndef LUMINA_SURFACE_CACHE_TEXEL_HLSLI
#define LUMINA_SURFACE_CACHE_TEXEL_HLSLI
// What an atlas pass knows about one texel: its card (one Load of the tile-to-card lookup, a
// 64x64-texel tile belongs to at most one card), whether a surface was captured there, and
// its world position (card space back to world through the capture depth).
//
// The includer names its resources first:
//
//   Texture2D<uint> gTileOwner;          // R32_UINT, one texel per atlas tile, LUMINA_NO_CARD where free
//   StructuredBuffer<SurfaceCard> gCards;
//   Texture2D<float> gCaptureDepth;      // card-space z of each captured texel
//   #define LUMINA_TILE_OWNER gTileOwner
//   #define LUMINA_SURFACE_CARD(i) gCards[i]
//   #define LUMINA_CAPTURE_DEPTH gCaptureDepth
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"

#if !defined(LUMINA_TILE_OWNER) || !defined(LUMINA_SURFACE_CARD) || !defined(LUMINA_CAPTURE_DEPTH)
#error "define LUMINA_TILE_OWNER, LUMINA_SURFACE_CARD(i) and LUMINA_CAPTURE_DEPTH before including surface_cache_texel.hlsli"
#endif

uint atlasTexelCard(uint2 texel) {
    return LUMINA_TILE_OWNER.Load(int3(texel / LUMINA_ATLAS_TILE_SIZE, 0));
}

// The inverse of the card's affine world-to-card map applied to card-space (u, v, z): rows
// a, b, c of the linear part invert to columns (b x c, c x a, a x b) / det.
float3 cardToWorldSpace(SurfaceCard card, float3 cardPoint) {
    float3 a = card.worldToCard0.xyz;
    float3 b = card.worldToCard1.xyz;
    float3 c = card.worldToCard2.xyz;
    float3 d = cardPoint - float3(card.worldToCard0.w, card.worldToCard1.w, card.worldToCard2.w);
    float det = dot(a, cross(b, c));
    return (cross(b, c) * d.x + cross(c, a) * d.y + cross(a, b) * d.z) / det;
}

// World position of the surface captured at an atlas texel of `card` (its centre).
float3 atlasTexelWorldPosition(SurfaceCard card, uint2 texel) {
    // texel is cast to int once, and the float comes from that int: vkd3d-shader merges two
    // casts of one value and then reads one as the other (docs/d3d12.md).
    int2 index = int2(texel);
    float2 uv = (float2(index) + 0.5f - float2(card.atlasRect.xy)) / float2(card.atlasRect.zw);
    float z = LUMINA_CAPTURE_DEPTH.Load(int3(index, 0));
    return cardToWorldSpace(card, float3(uv, z));
}

#if defined(LUMINA_SDF_GLOBAL)
// How far in front of a texel the buried test looks, in voxels of the global SDF cascade there.
// Two, whatever the radiosity's lift: near a concave edge the zero crossing runs up to a voxel in
// front of the true surface, and one voxel (threshold half a voxel) buried the texels along a
// closed room's edges, whose voxels then read nothing (furnace_0.95 at the low preset lost 6.8 %
// when the lift, which this distance used to be, went from two voxels to one; docs/gi.md, 16.).
#define LUMINA_BURIED_TEXEL_VOXELS 2.0f

// A texel buried in geometry: the point LUMINA_BURIED_TEXEL_VOXELS in front of it lies deeper
// than half that distance inside a solid (the floor under a block; a face lying on another
// surface). Nothing sees it, nothing lights it. Half, not zero: visible texels by a concave edge
// must not count as buried.
bool atlasTexelBuried(float3 world, float3 normal) {
    float distance = LUMINA_BURIED_TEXEL_VOXELS * sdfGlobalVoxelSizeAt(world);
    return sdfSampleGlobal(world + distance * normal) < -0.5f * distance;
}
#endif

// Texel `texelInTile` (row-major within the tile) of atlas tile `tile` (row-major in the atlas).
uint2 tileListTexel(uint tile, uint tilesPerRow, uint texelInTile) {
    uint2 tileOrigin = uint2(tile % tilesPerRow, tile / tilesPerRow) * LUMINA_ATLAS_TILE_SIZE;
    return tileOrigin + uint2(texelInTile % LUMINA_ATLAS_TILE_SIZE, texelInTile / LUMINA_ATLAS_TILE_SIZE);
}

#endif
