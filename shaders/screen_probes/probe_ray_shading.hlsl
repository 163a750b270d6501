// lumina-kernel: cs main
// Ray shading: each hit record to the radiance arriving along its ray. A miss sees the sky; a
// far-field hit reads the voxel lighting volume (RGBA16F over the world box voxelMin..voxelMax:
// rgb radiance leaving the surfaces in a voxel premultiplied by a, its occupancy), leaning back
// from the hit along its normal. Dividing the trilinear sample by its alpha keeps empty
// neighbour voxels from darkening a surface. Hits
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

// The filtered, occupancy-normalised volume at p, in the faces normal n points along when the
// volume has face columns (the surface cache's: surface_cache_lighting_shared.h), each weighted
// by the squared normal component; a = the filtered occupancy. The x coordinate is clamped half
// a texel inside its face column so the filter never blends two faces.
float4 voxelSample(float3 p, float3 n, uint3 dims) {
    const float3 uvw = (p - gSp.voxelMin.xyz) / (gSp.voxelMax.xyz - gSp.voxelMin.xyz);
    if (any(uvw < 0.0) || any(uvw > 1.0)) {
        return float4(0.0, 0.0, 0.0, 0.0);
    }
    const uint faces = max(uint(gSp.voxelMin.w), 1u);
    if (faces == 1u) {
        const float4 v = gVoxelLighting.SampleLevel(gLinearClamp, uvw, 0.0);
        return v.a > LUMINA_SP_MIN_OCCUPANCY ? float4(v.rgb / v.a, v.a) : float4(0.0, 0.0, 0.0, 0.0);
    }
    const float column = float(dims.x / faces);
    const float x = clamp(uvw.x * column, 0.5, column - 0.5);
    float4 sum = float4(0.0, 0.0, 0.0, 0.0);
    for (uint axis = 0u; axis < 3u; ++axis) {
        const float weight = n[axis] * n[axis];
        if (weight > 0.0) {
            const float face = float(2u * axis + (n[axis] < 0.0 ? 1u : 0u));
            const float u = (face * column + x) / float(dims.x);
            sum += weight * gVoxelLighting.SampleLevel(gLinearClamp, float3(u, uvw.yz), 0.0);
        }
    }
    return sum.a > LUMINA_SP_MIN_OCCUPANCY ? float4(sum.rgb / sum.a, sum.a) : float4(0.0, 0.0, 0.0, 0.0);
}

// A far-field hit lies in front of its surface: cone tracing stops once the distance falls
// below the cone's radius t x tan(half angle), and a coarse SDF's zero crossing sits up to half
// a mesh voxel off the triangles, while the voxels holding the surface's light are at or behind
// it (a wall on a voxel boundary fills only the voxels behind). A lookup at the hit itself reads
// the empty voxels in front; so the lookup leans back along the hit normal, half a voxel first
// (what voxel_lighting_sampling.hlsli does for sphere-traced hits), then in steps of at most a
// voxel across the cone's radius, and takes the first that finds a surface.
#define LUMINA_SP_MAX_VOXEL_LEANS 8u

float3 voxelRadiance(float3 position, float3 normal, float t) {
    if (!hasFlag(LUMINA_SP_FLAG_VOXEL_LIGHTING)) {
        return float3(0.0, 0.0, 0.0);
    }
    uint3 dims;
    gVoxelLighting.GetDimensions(dims.x, dims.y, dims.z);
    const float voxel = (gSp.voxelMax.x - gSp.voxelMin.x) * max(gSp.voxelMin.w, 1.0) / float(max(dims.x, 1u));
    const float reach = t * gSp.trace.y + voxel;
    const uint leans = clamp(uint(ceil(reach / voxel)), 1u, LUMINA_SP_MAX_VOXEL_LEANS);
    const float step = reach / float(leans);
    for (uint k = 0u; k <= leans; ++k) {
        const float4 v = voxelSample(position - (0.5 * voxel + float(k) * step) * normal, normal, dims);
        if (v.a > 0.0) {
            return v.rgb;
        }
    }
    return float3(0.0, 0.0, 0.0);
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
        const float3 radiance = miss ? gSp.sky.rgb : voxelRadiance(hit.positionAndT.xyz, hit.normalAndCoverage.xyz, hit.positionAndT.w);
        gRayRadiance[probe * rayCount + r] = float4(radiance, miss ? 0.0 : 1.0);
    }
}
