// lumina-kernel: cs main
// Ray shading: each hit record to the radiance arriving along its ray. A miss sees the sky; a
// far-field hit reads the voxel lighting volume (RGBA16F over the world box voxelMin..voxelMax:
// rgb radiance leaving the surfaces in a voxel premultiplied by a, its occupancy). Dividing the
// trilinear sample by its alpha keeps empty neighbour voxels from darkening a surface. Hits
// outside the volume, or with no volume given, are black: nothing is known about their light.
// One group per probe; thread t shades rays t, t + 64, ...
#include "screen_probes/screen_probe_common.hlsli"
#include "common/sdf_tracing.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<SdfHit> gHits : register(t1);
Texture3D<float4> gVoxelLighting : register(t2);
SamplerState gLinearClamp : register(s0);
RWStructuredBuffer<float4> gRayRadiance : register(u0); // rgb: radiance; a: 1 hit, 0 miss

// Occupancy below which a filtered voxel sample counts as empty.
#define LUMINA_SP_MIN_OCCUPANCY 1e-3

float3 voxelRadiance(float3 position) {
    if (!hasFlag(LUMINA_SP_FLAG_VOXEL_LIGHTING)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float3 uvw = (position - gSp.voxelMin.xyz) / (gSp.voxelMax.xyz - gSp.voxelMin.xyz);
    if (any(uvw < 0.0) || any(uvw > 1.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float4 v = gVoxelLighting.SampleLevel(gLinearClamp, uvw, 0.0);
    return v.a > LUMINA_SP_MIN_OCCUPANCY ? v.rgb / v.a : float3(0.0, 0.0, 0.0);
}

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.grid.w || !probeIsValid(gProbes[probe])) {
        return;
    }
    const uint rayCount = gSp.rays.x;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const SdfHit hit = gHits[probe * rayCount + r];
        const bool miss = sdfIsMiss(hit);
        const float3 radiance = miss ? gSp.sky.rgb : voxelRadiance(hit.positionAndT.xyz);
        gRayRadiance[probe * rayCount + r] = float4(radiance, miss ? 0.0 : 1.0);
    }
}
