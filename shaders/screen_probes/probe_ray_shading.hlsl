// lumina-kernel: cs main
// Ray shading: each hit record to the radiance arriving along its ray. A near-field hit
// (LUMINA_SP_FLAG_NEAR_FIELD) brings its radiance from the surface cache with it. A miss sees the
// sky along its direction (common/sky_sampling.hlsli). A far-field hit reads the voxel lighting volume, in
// one of two conventions:
// - the caller's (RGBA16F over the world box voxelMin..voxelMax: rgb radiance leaving the surfaces
//   in a voxel premultiplied by a, its occupancy): the trilinear sample divided by its alpha, so
//   empty neighbour voxels do not darken a surface;
// - the surface cache's (LUMINA_SP_FLAG_VOXEL_GRID: rgb mean radiance, a coverage, one column per
//   face direction): the faces of the hit normal turned to face the ray (sdfFacingNormal) that
//   the ray can see, coverage-weighted and leaning along -normal, since a cone hit stops in front
//   of its surface, in empty voxels (coneHitVoxelRadiance).
// Hits outside the volume, or with no volume given, are black: nothing is known about their light.
// One group per probe; thread t shades rays t, t + 64, ...
#include "screen_probes/screen_probe_common.hlsli"
#include "common/sdf_tracing.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<SdfHit> gHits : register(t1);
Texture3D<float4> gVoxelLighting : register(t2);
StructuredBuffer<float4> gNearField : register(t3); // a: LUMINA_SP_NEAR_*, with LUMINA_SP_FLAG_NEAR_FIELD
StructuredBuffer<ProbeRay> gRays : register(t4);
Texture2D<float4> gSky : register(t5);
SamplerState gLinearClamp : register(s0);
RWStructuredBuffer<float4> gRayRadiance : register(u0); // rgb: radiance; a: 1 hit, 0 miss

#define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/voxel_lighting_sampling.hlsli"
#define LUMINA_SKY_TEXTURE gSky
#include "common/sky_sampling.hlsli"

// A cone stops once the global SDF falls below its radius r = t tan(angle), so its hit lies in
// front of the surface by about r, and by the global SDF's shell around open surfaces (half a
// global voxel and 0.6 mesh voxels, docs/sdf.md) more. So the lookup walks back along -n in voxel
// steps, from half a voxel to LUMINA_SP_CONE_LEAN_RADII r + LUMINA_SP_CONE_LEAN_VOXELS voxels (at
// most LUMINA_SP_CONE_LEAN_STEPS lookups), and takes the first that finds a surface: the nearest
// surface behind the hit, never one beyond it. Measured in the emissive Cornell box (the cache's 64^3
// volume, near field off): the first covered voxel lies 1 to 2 r behind most hits; no surface was
// found for 91% of the hits at the hit, 67% within sampleVoxelLighting's 1.5 voxels, 2.8% with the
// walk (docs/screen_probes.md).
#define LUMINA_SP_CONE_LEAN_RADII 2.0
#define LUMINA_SP_CONE_LEAN_VOXELS 2.0
#define LUMINA_SP_CONE_LEAN_STEPS 32u

// One return per function, and none inside a loop: with an early return in the lean loop,
// vkd3d-shader's DXBC made every far hit black on D3D12 under Wine (docs/d3d12.md).
float3 coneHitVoxelRadiance(SdfHit hit, float3 direction) {
    const float voxel = gSp.voxelGrid.voxelSize;
    const float3 p = hit.positionAndT.xyz;
    const float3 n = sdfFacingNormal(hit.normalAndCoverage.xyz, direction, hit.positionAndT.w);
    const float3 seenFrom = sdfSeenFrom(direction, hit.positionAndT.w);
    const float radius = hit.positionAndT.w * gSp.coneTanHalfAngle;
    const float reach = LUMINA_SP_CONE_LEAN_RADII * radius + LUMINA_SP_CONE_LEAN_VOXELS * voxel;
    float3 radiance = float3(0.0, 0.0, 0.0);
    bool found = false;
    float lean = 0.5 * voxel;
    for (uint step = 0u; step < LUMINA_SP_CONE_LEAN_STEPS && lean <= reach && !found; ++step) {
        const float4 v = voxelLightingTrilinear(gSp.voxelGrid, p - lean * n, n, seenFrom);
        found = v.a > 0.0;
        radiance = found ? v.rgb : radiance;
        lean += voxel;
    }
    return radiance;
}

float3 voxelRadiance(SdfHit hit, float3 direction) {
    float3 radiance = float3(0.0, 0.0, 0.0);
    if (hasFlag(LUMINA_SP_FLAG_VOXEL_LIGHTING)) {
        const float3 position = hit.positionAndT.xyz;
        const float3 uvw = (position - gSp.voxelMin) / (gSp.voxelMax - gSp.voxelMin);
        if (hasFlag(LUMINA_SP_FLAG_VOXEL_GRID)) {
            radiance = coneHitVoxelRadiance(hit, direction);
        } else if (all(uvw >= 0.0) && all(uvw <= 1.0)) {
            const float4 v = gVoxelLighting.SampleLevel(gLinearClamp, uvw, 0.0);
            radiance = v.a > LUMINA_SP_MIN_COVERAGE ? v.rgb / v.a : float3(0.0, 0.0, 0.0);
        }
    }
    return radiance;
}

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const uint rayCount = gSp.raysPerProbe;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const uint ray = probe * rayCount + r;
        if (hasFlag(LUMINA_SP_FLAG_NEAR_FIELD)) {
            const float4 near = gNearField[ray];
            if (near.a != float(LUMINA_SP_NEAR_MISS)) {
                gRayRadiance[ray] = float4(near.rgb, 1.0);
                continue;
            }
        }
        const SdfHit hit = gHits[ray];
        const bool miss = sdfIsMiss(hit);
        const float3 direction = gRays[ray].directionAndWeight.xyz;
        const float3 radiance = miss ? skyRadiance(direction) : voxelRadiance(hit, direction);
        gRayRadiance[ray] = float4(radiance, miss ? 0.0 : 1.0);
    }
}
