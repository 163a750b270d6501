// lumina-kernel: cs main
// Pass 5, near-field trace: every ray of every valid probe sphere-traced through the mesh SDFs
// (sdfTraceNearField: the instance BVH, closest hit) from the far field's origin, up to the
// near-field distance (nearFieldDistance). A hit finds the card that owns it through the card BVH
// (findCardOwner, the rule of card_bvh_shared.h, the hit instance's cards first) and reads the
// surface cache's final layer there: the outgoing radiance of the surface, i.e. the radiance
// arriving back along the ray. Where no card owns the hit, or none of the card's texels around it
// were captured, the voxel lighting at the hit stands in (sampleVoxelLighting). Writes the hit
// record (the far field replaces the misses' with its own) and the near-field result (rgb
// radiance, a: LUMINA_SP_NEAR_*).
// One group per probe; thread t traces rays t, t + 64, ...
#include "screen_probes/probe_trace_common.hlsli"
#include "surface_cache/card_bvh_shared.h"

StructuredBuffer<CardBvhNode> gCardBvh : register(t8);
StructuredBuffer<SurfaceCard> gCards : register(t9);
Texture2D<float4> gFinalLighting : register(t10); // outgoing radiance; a = 1 where a surface was captured
Texture3D<float4> gVoxelLighting : register(t11); // rgb mean radiance, a coverage (over gSp.voxelGrid)
RWStructuredBuffer<SdfHit> gHits : register(u0);
RWStructuredBuffer<float4> gNearField : register(u1);

#define LUMINA_CARD_BVH_NODE(i) gCardBvh[i]
#define LUMINA_SURFACE_CARD(i) gCards[i]
#include "surface_cache/card_bvh_traversal.hlsli"
#define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/voxel_lighting_sampling.hlsli"
#define LUMINA_FINAL_LIGHTING gFinalLighting
#include "surface_cache/card_radiance.hlsli"

// Radiance leaving the surface at a near-field hit towards the probe, and where it came from.
float4 nearFieldRadiance(SdfHit hit, float3 direction) {
    const float3 p = hit.positionAndT.xyz;
    // The side the ray came from, also on open (unsigned) surfaces (sdfFacingNormal).
    const float3 n = sdfFacingNormal(hit.normalAndCoverage.xyz, direction, hit.positionAndT.w);
    const float3 seenFrom = sdfSeenFrom(direction, hit.positionAndT.w);
    const CardOwner owner = findCardOwner(p, n, hit.ids.x, seenFrom);
    if (owner.card != LUMINA_NO_CARD) {
        const float4 card = cardRadiance(gCards[owner.card], p);
        if (card.a > 0.0) {
            return float4(card.rgb, float(LUMINA_SP_NEAR_CARD));
        }
    }
    return float4(sampleVoxelLighting(gSp.voxelGrid, p, n, seenFrom), float(LUMINA_SP_NEAR_VOXEL));
}

// Traces ray `ray` of `probe`, whose origin is `origin`: the hit record and the near-field result.
void traceNearField(uint ray, ScreenProbe probe, float3 origin) {
    const float3 direction = gRays[ray].directionAndWeight.xyz;
    const float3 start = probeRayStart(probe, origin, direction);
    const SdfHit hit = sdfTraceNearField(start, direction, 0.0, sdfDefaultTraceParams(gSp.nearFieldDistance));
    gHits[ray] = hit;
    gNearField[ray] = sdfIsMiss(hit) ? float4(0.0, 0.0, 0.0, float(LUMINA_SP_NEAR_MISS))
                                     : nearFieldRadiance(hit, direction);
}

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group
                                                     : SV_GroupID, uint t
                                                     : SV_GroupIndex) {
    uint probe;
    float3 origin;
    if (!tracedProbe(group, t, probe, origin)) {
        return;
    }
    for (uint r = t; r < gSp.raysPerProbe; r += LUMINA_SP_PROBE_TEXELS) {
        traceNearField(probe * gSp.raysPerProbe + r, gProbes[probe], origin);
    }
}
