// lumina-kernel: cs main
// Direct light of the atlas (gi/surface_cache/surface_cache_direct_light_pass.h): the
// irradiance every light delivers to each texel of the listed tiles, with the deferred
// renderer's lights, units and shadow maps (lights_shared.h, shadow_visibility.hlsli), so that
// the cache and the screen agree. Irradiance, not radiance: combine applies albedo / pi. A
// light is evaluated only where the card's light mask says it can reach.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "deferred/deferred_shared.h"
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"

LUMINA_PUSH_CONSTANTS(SurfaceDirectLightConstants, gConstants);
ConstantBuffer<DeferredShadowConstants> gShadow : register(b0);
Texture2D<float> gSunShadow : register(t0);         // D32, depth 0 nearest the sun
Texture2DArray<float> gPointShadows : register(t1); // R32F cube array seen as 2D array layers
StructuredBuffer<DeferredLight> gLights : register(t2);
Texture2DArray<float4> gSurface : register(t3); // layer 0 normal (a = captured)
Texture2D<uint> gTileOwner : register(t4);
StructuredBuffer<SurfaceCard> gCards : register(t5);
Texture2D<float> gCaptureDepth : register(t6);
StructuredBuffer<uint> gTiles : register(t7);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gDirect : register(u0);

#define LUMINA_SHADOW_CONSTANTS gShadow
#define LUMINA_SUN_SHADOW_MAP gSunShadow
#define LUMINA_POINT_SHADOW_MAPS gPointShadows
#include "deferred/shadow_visibility.hlsli"
#define LUMINA_TILE_OWNER gTileOwner
#define LUMINA_SURFACE_CARD(i) gCards[i]
#define LUMINA_CAPTURE_DEPTH gCaptureDepth
#include "surface_cache/surface_cache_texel.hlsli"

// Largest finite half: the direct layer is RGBA16F.

bool cardSeesLight(SurfaceCard card, uint light) {
    return light < LUMINA_CARD_LIGHT_MASK_BITS && (card.lightMask[light / 32u] & (1u << (light % 32u))) != 0u;
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint entry, item;
    if (!tileListItem(id.xy, gConstants.tileCount, LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE, entry, item)) {
        return;
    }
    uint2 texel = tileListTexel(gTiles[entry], gConstants.tilesPerRow, item);
    float4 normal = gSurface.Load(int4(texel, 0, 0));
    uint cardIndex = atlasTexelCard(texel);
    if (normal.a == 0.0f || cardIndex == LUMINA_NO_CARD) {
        gDirect[texel] = float4(0.0f, 0.0f, 0.0f, 0.0f);
        return;
    }
    SurfaceCard card = gCards[cardIndex];
    float3 n = normalize(normal.xyz);
    float3 position = atlasTexelWorldPosition(card, texel);
    float3 irradiance = float3(0.0f, 0.0f, 0.0f);
    for (uint i = 0u; i < gConstants.lightCount; ++i) {
        if (!cardSeesLight(card, i)) {
            continue;
        }
        DeferredLight light = gLights[i];
        LightSample sample = evaluateLight(light.light, position);
        float cosine = dot(n, sample.direction);
        if (cosine > 0.0f && any(sample.irradiance > 0.0f)) {
            irradiance += sample.irradiance * (cosine * shadowVisibility(light, position, n));
        }
    }
    bool finite = !(any(isnan(irradiance)) || any(isinf(irradiance)));
    irradiance = finite ? min(irradiance, LUMINA_HALF_MAX) : float3(0.0f, 0.0f, 0.0f);
    gDirect[texel] = roundToHalf(float4(irradiance, 1.0f));
}
