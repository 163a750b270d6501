// lumina-kernel: cs inject
// lumina-kernel: cs resolve
// Voxel lighting (gi/surface_cache/voxel_lighting_pass.h): a 64^3 RGBA16F volume of the final
// layer's outgoing radiance over the scene bounds, the low-frequency fallback for ray hits
// far from the camera (and the radiance radiosity rays read).
//   inject:  one thread per texel of the listed tiles; a captured texel adds its radiance to
//            the voxel holding its world position (fixed-point atomics: RGBA16F has none), into
//            the faces its normal points along (LUMINA_VOXEL_FACES), each weighted by the squared
//            normal component (the weights sum to 1) times the texel's world area.
//            A texel buried in geometry (the floor under a block, the block's face on the floor:
//            the global SDF is negative just in front of it) is seen by nothing and adds nothing,
//            or it would darken the visible surfaces that share its voxels.
//   resolve: one thread per voxel face; rgb = area-weighted mean radiance of the texels it received,
//            a = 1 where it received any (coverage, which the lookup weights by), then zeroes the
//            accumulator for the next update.
#include "common/constants_shared.h"
#include "sdf/sdf_scene_bindings.hlsli"
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"

LUMINA_PUSH_CONSTANTS(VoxelInjectConstants, gConstants);
Texture2D<float4> gFinal : register(t6);
Texture2DArray<float4> gSurface : register(t7);
Texture2D<uint> gTileOwner : register(t8);
StructuredBuffer<SurfaceCard> gCards : register(t9);
Texture2D<float> gCaptureDepth : register(t10);
StructuredBuffer<uint> gTiles : register(t11);
// Per voxel face: r, g, b and the summed weight, in fixed point.
RWStructuredBuffer<uint> gAccumulator : register(u0);
LUMINA_UAV_FORMAT(rgba16f) RWTexture3D<float4> gVoxels : register(u1);

#define LUMINA_TILE_OWNER gTileOwner
#define LUMINA_SURFACE_CARD(i) gCards[i]
#define LUMINA_CAPTURE_DEPTH gCaptureDepth
#include "surface_cache/surface_cache_texel.hlsli"

// A texel's world area over the nominal texel's. A card's rectangle is rounded up to whole tiles,
// so a small card has more texels per square metre than a large one (two_rooms' 1.2 m panel: 1.64
// times the ceiling's), and a voxel that averaged texels, not area, let the denser card outweigh
// the other: the panel's edge voxels read brighter than the panel and the ceiling around it
// (docs/gi.md, energy). Card space maps the card's extent to [0, 1]^2, so the row lengths are
// the inverse width and height. Capped at 16 (a card at a quarter of full density along each
// axis), which keeps a voxel's fixed-point sum under 2^32 for 1,024 such texels.
#define LUMINA_VOXEL_MAX_AREA_WEIGHT 16.0f
float texelAreaWeight(SurfaceCard card) {
    float area = 1.0f / (length(card.worldToCard0.xyz) * length(card.worldToCard1.xyz) *
                         float(card.atlasRect.z) * float(card.atlasRect.w));
    float weight = area / gConstants.nominalTexelArea;
    // NaN or 0 (a degenerate card) weighs as a texel at full density.
    return weight > 0.0f ? min(weight, LUMINA_VOXEL_MAX_AREA_WEIGHT) : 1.0f;
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void inject(uint3 id
                                   : SV_DispatchThreadID) {
    uint entry, item;
    if (!tileListItem(id.xy, gConstants.tileCount, LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE, entry,
                      item)) {
        return;
    }
    uint2 texel = tileListTexel(gTiles[entry], gConstants.tilesPerRow, item);
    uint card = atlasTexelCard(texel);
    float4 normal = gSurface.Load(int4(texel, 0, 0));
    if (card == LUMINA_NO_CARD || normal.a == 0.0f) {
        return;
    }
    float3 world = atlasTexelWorldPosition(gCards[card], texel);
    if (atlasTexelBuried(world, normalize(normal.xyz))) {
        return;
    }
    float3 local = (world - gConstants.grid.boxMin) / gConstants.grid.voxelSize;
    int3 voxel = int3(floor(local));
    int3 dims = int3(gConstants.grid.dims);
    if (any(voxel < 0) || any(voxel >= dims) || any(isnan(world))) {
        return;
    }
    // The final layer is finite by construction (combine); the clamp keeps the sum in range.
    float3 radiance = clamp(gFinal.Load(int3(texel, 0)).rgb, 0.0f, LUMINA_VOXEL_MAX_RADIANCE);
    float3 n = normalize(normal.xyz);
    float area = texelAreaWeight(gCards[card]);
    for (uint axis = 0u; axis < 3u; ++axis) {
        float weight = n[axis] * n[axis] * area;
        uint fixedWeight = uint(weight * LUMINA_VOXEL_FIXED_POINT_SCALE + 0.5f);
        if (fixedWeight == 0u) {
            continue;
        }
        uint face = 2u * axis + (n[axis] < 0.0f ? 1u : 0u);
        // Radiance times the rounded weight: resolve divides by the sum of rounded weights, so a
        // uniform radiance resolves exactly whatever each weight rounded to (a weight of 0.4
        // rounds 0.4 % low, which the unrounded product turned into 0.4 % too bright).
        uint3 fixedPoint = uint3(radiance * float(fixedWeight) + 0.5f);
        uint base = 4u * uint(int(face) * dims.x + voxel.x +
                              LUMINA_VOXEL_FACES * dims.x * (voxel.y + dims.y * voxel.z));
        uint ignored;
        InterlockedAdd(gAccumulator[base + 0u], fixedPoint.x, ignored);
        InterlockedAdd(gAccumulator[base + 1u], fixedPoint.y, ignored);
        InterlockedAdd(gAccumulator[base + 2u], fixedPoint.z, ignored);
        InterlockedAdd(gAccumulator[base + 3u], fixedWeight, ignored);
    }
}

[numthreads(LUMINA_VOLUME_GROUP_SIZE, LUMINA_VOLUME_GROUP_SIZE, LUMINA_VOLUME_GROUP_SIZE)]
void resolve(uint3 id : SV_DispatchThreadID) {
    // id.x runs over the faces' side-by-side columns.
    uint3 dims = uint3(LUMINA_VOXEL_FACES * gConstants.grid.dims.x, gConstants.grid.dims.yz);
    if (any(id >= dims)) {
        return;
    }
    uint base = 4u * (id.x + dims.x * (id.y + dims.y * id.z));
    uint weight = gAccumulator[base + 3u];
    float4 value = float4(0.0f, 0.0f, 0.0f, 0.0f);
    if (weight > 0u) {
        float3 sum = float3(gAccumulator[base + 0u], gAccumulator[base + 1u], gAccumulator[base + 2u]);
        value = float4(sum / float(weight), 1.0f);
    }
    gVoxels[id] = roundToHalfDithered(value, ditherOf(id, gConstants.updateIndex ^ 0x9e3779b9u));
    for (uint c = 0u; c < 4u; ++c) {
        gAccumulator[base + c] = 0u;
    }
}
