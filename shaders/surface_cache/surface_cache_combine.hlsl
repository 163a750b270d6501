// lumina-kernel: cs main
// Combine (gi/surface_cache/surface_cache_combine_pass.h): the final layer's outgoing radiance
// from the lighting layers, one thread per texel of the listed tiles:
//   L = (E_direct + E_indirect) * albedo / pi + Le
// Direct and indirect hold irradiance, so albedo / pi is the Lambert BRDF; Le (the material
// layer's rgb) is how emissive surfaces enter the GI. The final layer feeds the voxel lighting
// and the next bounce, so nothing non-finite may reach it.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "surface_cache/surface_cache_lighting_shared.h"

// Largest finite half: the final layer is RGBA16F, and an overflow would become +inf.

LUMINA_PUSH_CONSTANTS(AtlasTileListConstants, gConstants);
Texture2D<float4> gAlbedo : register(t0);
Texture2DArray<float4> gSurface : register(t1); // layer 0 normal (a = captured), 1 material
Texture2D<float4> gDirect : register(t2);
Texture2D<float4> gIndirect : register(t3);
StructuredBuffer<uint> gTiles : register(t4);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gFinal : register(u0);

float3 finiteOrZero(float3 v) {
    return (any(isnan(v)) || any(isinf(v))) ? float3(0.0f, 0.0f, 0.0f) : v;
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id
                                 : SV_DispatchThreadID) {
    uint entry, item;
    if (!tileListItem(id.xy, gConstants.tileCount, LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE, entry,
                      item)) {
        return;
    }
    uint tile = gTiles[entry];
    uint2 tileOrigin = uint2(tile % gConstants.tilesPerRow, tile / gConstants.tilesPerRow) * LUMINA_ATLAS_TILE_SIZE;
    uint2 texel = tileOrigin + uint2(item % LUMINA_ATLAS_TILE_SIZE, item / LUMINA_ATLAS_TILE_SIZE);
    float4 normal = gSurface.Load(int4(texel, 0, 0));
    if (normal.a == 0.0f) {
        gFinal[texel] = float4(0.0f, 0.0f, 0.0f, 0.0f); // no surface: no light
        return;
    }
    float3 albedo = gAlbedo.Load(int3(texel, 0)).rgb;
    float3 emission = finiteOrZero(gSurface.Load(int4(texel, 1, 0)).rgb);
    float3 irradiance =
        finiteOrZero(gDirect.Load(int3(texel, 0)).rgb) + finiteOrZero(gIndirect.Load(int3(texel, 0)).rgb);
    float3 radiance = max(irradiance, 0.0f) * albedo * LUMINA_INV_PI + max(emission, 0.0f);
    gFinal[texel] = roundToHalfDithered(float4(min(radiance, LUMINA_HALF_MAX), 1.0f),
                                        ditherOf(uint3(texel, 0u), gConstants.updateIndex));
}
