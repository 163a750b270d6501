// lumina-kernel: cs main
// Ray shading: each hit record to the radiance arriving along its ray. A near-field hit
// (LUMINA_SP_FLAG_NEAR_FIELD) brings its radiance from the surface cache with it. A miss sees the
// sky. A far-field hit reads the voxel lighting volume, in one of two conventions:
// - the caller's (RGBA16F over the world box voxelMin..voxelMax: rgb radiance leaving the surfaces
//   in a voxel premultiplied by a, its occupancy): the trilinear sample divided by its alpha, so
//   empty neighbour voxels do not darken a surface;
// - the surface cache's (LUMINA_SP_FLAG_VOXEL_GRID): sampleVoxelLighting, coverage-weighted and
//   leaning along -normal, since a cone hit stops in front of its surface, in empty voxels.
// Hits outside the volume, or with no volume given, are black: nothing is known about their light.
// One group per probe; thread t shades rays t, t + 64, ...
#include "screen_probes/screen_probe_common.hlsli"
#include "common/sdf_tracing.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<SdfHit> gHits : register(t1);
Texture3D<float4> gVoxelLighting : register(t2);
StructuredBuffer<float4> gNearField : register(t3); // a: LUMINA_SP_NEAR_*, with LUMINA_SP_FLAG_NEAR_FIELD
SamplerState gLinearClamp : register(s0);
RWStructuredBuffer<float4> gRayRadiance : register(u0); // rgb: radiance; a: 1 hit, 0 miss

#define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/voxel_lighting_sampling.hlsli"

float3 voxelRadiance(SdfHit hit) {
    if (!hasFlag(LUMINA_SP_FLAG_VOXEL_LIGHTING)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float3 position = hit.positionAndT.xyz;
    if (hasFlag(LUMINA_SP_FLAG_VOXEL_GRID)) {
        return sampleVoxelLighting(gSp.voxelGrid, position, hit.normalAndCoverage.xyz);
    }
    const float3 uvw = (position - gSp.voxelMin.xyz) / (gSp.voxelMax.xyz - gSp.voxelMin.xyz);
    if (any(uvw < 0.0) || any(uvw > 1.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float4 v = gVoxelLighting.SampleLevel(gLinearClamp, uvw, 0.0);
    return v.a > LUMINA_SP_MIN_COVERAGE ? v.rgb / v.a : float3(0.0, 0.0, 0.0);
}

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.grid.w || !probeIsValid(gProbes[probe])) {
        return;
    }
    const uint rayCount = gSp.rays.x;
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
        const float3 radiance = miss ? gSp.sky.rgb : voxelRadiance(hit);
        gRayRadiance[ray] = float4(radiance, miss ? 0.0 : 1.0);
    }
}
