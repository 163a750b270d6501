// lumina-kernel: cs main
// DDGI trace: every ray of every probe, sphere-traced through the SDFs from the probe's relocated
// position: the mesh SDFs (sdfTraceNearField) up to the near-field distance, the global SDF
// beyond it. A near hit reads the surface cache's final lighting on the card that owns it
// (cardRadiance), a far hit or a hit no card covers the cache's voxel lighting, a miss the sky:
// so the radiance of every bounce the surface cache holds comes back along the ray. A hit on
// the back of a surface (its SDF normal along the ray: the probe sits inside a closed mesh) is
// recorded with a negative distance and no radiance.
// Inactive probes trace their fixed rays only (classification needs them to wake up).
// One group per probe; thread t traces rays t, t + 64, ... Writes float4 per ray: rgb radiance,
// a: hit distance (negative: back face; the max trace distance: miss).
#include "ddgi/ddgi_common.hlsli"
#include "sdf/sdf_scene_bindings.hlsli"
#include "surface_cache/card_bvh_shared.h"

StructuredBuffer<DdgiProbe> gProbes : register(t6);
StructuredBuffer<CardBvhNode> gCardBvh : register(t7);
StructuredBuffer<SurfaceCard> gCards : register(t8);
Texture2D<float4> gFinalLighting : register(t9);  // outgoing radiance; a = 1 where captured
Texture3D<float4> gVoxelLighting : register(t10); // rgb mean radiance, a coverage (gDdgi.voxelGrid)
Texture2D<float4> gSky : register(t11);
RWStructuredBuffer<float4> gRayData : register(u0);

#define LUMINA_CARD_BVH_NODE(i) gCardBvh[i]
#define LUMINA_SURFACE_CARD(i) gCards[i]
#include "surface_cache/card_bvh_traversal.hlsli"
#define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/voxel_lighting_sampling.hlsli"
#define LUMINA_FINAL_LIGHTING gFinalLighting
#include "surface_cache/card_radiance.hlsli"
#define LUMINA_SKY_TEXTURE gSky
#include "common/sky_sampling.hlsli"

// The surface cache's radiance leaving a hit towards the probe: its card's final lighting (the
// hit instance's cards first), or the voxel lighting where no card covers it.
float3 hitRadiance(float3 p, float3 n, float3 seenFrom, uint instance, bool nearField) {
    if (nearField) {
        const CardOwner owner = findCardOwner(p, n, instance, seenFrom);
        if (owner.card != LUMINA_NO_CARD) {
            const float4 card = cardRadiance(gCards[owner.card], p);
            if (card.a > 0.0) {
                return card.rgb;
            }
        }
    }
    return sampleVoxelLighting(gDdgi.voxelGrid, p, n, seenFrom);
}

float4 traceRay(float3 origin, float3 direction) {
    const float nearDistance = gDdgi.nearFieldDistance;
    const float maxDistance = gDdgi.maxTraceDistance;
    SdfHit hit = sdfTraceNearField(origin, direction, 0.0, sdfDefaultTraceParams(nearDistance));
    bool nearField = true;
    if (sdfIsMiss(hit) && nearDistance < maxDistance) {
        hit = sdfTraceGlobal(origin, direction, nearDistance, sdfDefaultTraceParams(maxDistance));
        nearField = false;
    }
    if (sdfIsMiss(hit)) {
        return float4(skyRadiance(direction), maxDistance);
    }
    const float t = hit.positionAndT.w;
    const float3 n = hit.normalAndCoverage.xyz;
    // A signed field's gradient points out of its solid: along the ray, the ray left from inside.
    if (dot(n, direction) > 0.0) {
        return float4(0.0, 0.0, 0.0, -max(t, 1e-6 * maxDistance));
    }
    const float3 facing = dot(n, n) > 0.0 ? n : -direction;
    const float3 radiance = hitRadiance(hit.positionAndT.xyz, facing, sdfSeenFrom(direction, t), hit.ids.x, nearField);
    return float4(ddgiSanitise(radiance), t);
}

groupshared float4 gsProbe; // xyz: ray origin; w: rays to trace

[numthreads(LUMINA_DDGI_TRACE_GROUP, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = group.x;
    if (probe >= gDdgi.probeCount) {
        return;
    }
    if (t == 0u) {
        const DdgiProbe p = gProbes[probe];
        const uint rays = ddgiProbeInactive(p) ? gDdgi.fixedRays : gDdgi.raysPerProbe;
        gsProbe = float4(ddgiProbePosition(ddgiProbeRef(probe), p), float(rays));
    }
    GroupMemoryBarrierWithGroupSync();
    const float3 origin = gsProbe.xyz;
    const uint rays = uint(gsProbe.w);
    for (uint r = t; r < rays; r += LUMINA_DDGI_TRACE_GROUP) {
        gRayData[probe * gDdgi.raysPerProbe + r] = traceRay(origin, ddgiRayDirection(r));
    }
}
