// lumina-kernel: cs main
// DDGI sampling: the irradiance E at every pixel's surface from the eight probes of the cell
// around it, in the finest volume that holds it (blended into the next one over the outer half
// cell of a cascade). Each probe weighs
//   trilinear (its corner of the cell)
//   x wrap shading: ((1 + n.w) / 2)^2 + 0.2, w towards the probe: probes behind the surface count
//     less, but never nothing, so a thin corner of the lattice still has a probe to read
//   x Chebyshev visibility: from the probe's mean distance m and mean squared distance m2 towards
//     the point, variance s2 = |m2 - m^2|; a point farther than m is lit by the probe with at most
//     s2 / (s2 + (r - m)^2), cubed to sharpen the cut-off; 1 when it is nearer than m
//   with tiny weights crushed (weights below 0.2 fall with their cube): light that leaks through
//   a wall arrives with a small weight, and this removes most of what is left.
// The point is biased off the surface, along its normal and towards the camera, before the
// visibility test (so it does not test against the surface it lies on). Inactive probes weigh
// nothing. Irradiance is decoded per texel (ddgiDecodeIrradiance) and interpolated bilinearly;
// distances are filtered by the sampler. Sky pixels get 0.
#include "ddgi/ddgi_common.hlsli"
#include "screen_probes/octahedral_shared.h"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<DdgiProbe> gProbes : register(t2);
Texture2D<float4> gIrradiance : register(t3);
Texture2D<float2> gDistance : register(t4);
SamplerState gLinearClamp : register(s0);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gOut : register(u0); // rgb: irradiance E; a: 1 on surfaces

#define LUMINA_DDGI_WRAP_FLOOR 0.2
#define LUMINA_DDGI_CRUSH_THRESHOLD 0.2
#define LUMINA_DDGI_MIN_WEIGHT 1e-6

// E in direction n from the irradiance tile at `tile`: the four texels around n, each decoded.
float3 probeIrradiance(uint2 tile, float3 n) {
    const float2 x =
        float2(tile) + 1.0 + (octEncode(n) * 0.5 + 0.5) * float(LUMINA_DDGI_IRRADIANCE_SIZE) - 0.5;
    const float2 base = floor(x);
    const float2 f = x - base;
    float3 sum = float3(0.0, 0.0, 0.0);
    for (uint corner = 0u; corner < 4u; ++corner) {
        const float2 offset = float2(corner & 1u, corner >> 1);
        const float2 w2 = lerp(1.0 - f, f, offset);
        const float3 s = gIrradiance.Load(int3(int2(base + offset), 0)).rgb;
        sum += w2.x * w2.y *
               float3(ddgiDecodeIrradiance(s.r), ddgiDecodeIrradiance(s.g), ddgiDecodeIrradiance(s.b));
    }
    return sum;
}

// Mean and mean squared distance (in the volume's unit) towards direction d.
float2 probeDistance(uint2 tile, float3 d) {
    const float2 texel = float2(tile) + 1.0 + (octEncode(d) * 0.5 + 0.5) * float(LUMINA_DDGI_DISTANCE_SIZE);
    return gDistance.SampleLevel(gLinearClamp, texel / float2(gDdgi.distanceAtlasSize), 0.0);
}

// rgb: E at p (normal n, unit vector v towards the camera) from volume v; a: the summed weight (0:
// no probe).
float4 sampleVolume(uint v, float3 p, float3 n, float3 towardsCamera) {
    const DdgiVolumeInfo volume = gDdgi.volumes[v];
    // Biases are fractions of the volume's smallest spacing: each cascade biases by its own cells.
    const float cell = min(volume.spacing.x, min(volume.spacing.y, volume.spacing.z));
    const float3 q = p + cell * (gDdgi.normalBias * n + gDdgi.viewBias * towardsCamera);
    const int3 last = int3(volume.counts) - 1;
    const float3 grid = (p - volume.origin) / volume.spacing;
    const int3 base = clamp(int3(floor(grid)), int3(0, 0, 0), max(last - 1, int3(0, 0, 0)));
    const float3 alpha = saturate(grid - float3(base));
    float3 sum = float3(0.0, 0.0, 0.0);
    float weightSum = 0.0;
    for (uint corner = 0u; corner < 8u; ++corner) {
        const int3 offset = int3(corner & 1u, (corner >> 1) & 1u, corner >> 2);
        const uint3 c = uint3(min(base + offset, last));
        const uint local = ddgiProbeIndex(ddgiSlotOfLattice(volume, c), volume.counts);
        const DdgiProbe probe = gProbes[volume.firstProbe + local];
        if (ddgiProbeInactive(probe)) {
            continue;
        }
        const float3 probePosition = ddgiLatticePosition(volume, c) + probe.offsetAndState.xyz;
        const float3 trilinear3 = lerp(1.0 - alpha, alpha, float3(offset));
        const float trilinear = trilinear3.x * trilinear3.y * trilinear3.z;

        const float3 towardsProbe = normalize(probePosition - p);
        const float wrap = 0.5 * (dot(towardsProbe, n) + 1.0);
        float weight = wrap * wrap + LUMINA_DDGI_WRAP_FLOOR;

        const float3 probeToPoint = q - probePosition;
        const float r = length(probeToPoint) / volume.distanceUnit;
        const float2 moments = probeDistance(ddgiTileOrigin(volume, local, LUMINA_DDGI_DISTANCE_TILE),
                                             r > 0.0 ? probeToPoint / (r * volume.distanceUnit) : n);
        if (r > moments.x) {
            const float variance = abs(moments.y - moments.x * moments.x);
            const float excess = r - moments.x;
            const float chebyshev = variance / (variance + excess * excess);
            weight *= chebyshev * chebyshev * chebyshev;
        }
        weight = max(weight, LUMINA_DDGI_MIN_WEIGHT);
        if (weight < LUMINA_DDGI_CRUSH_THRESHOLD) {
            weight *= weight * weight / (LUMINA_DDGI_CRUSH_THRESHOLD * LUMINA_DDGI_CRUSH_THRESHOLD);
        }
        weight *= trilinear;
        sum += weight * probeIrradiance(ddgiTileOrigin(volume, local, LUMINA_DDGI_IRRADIANCE_TILE), n);
        weightSum += weight;
    }
    return float4(sum, weightSum);
}

// 1 where the volume's lattice (grown by half a cell) holds p and the volume is not the coarsest,
// falling to 0 across the outer half cell so the next volume takes over smoothly; the coarsest
// volume holds everything (points outside it read its boundary probes).
float volumeCoverage(uint v, float3 p) {
    if (v + 1u == gDdgi.volumeCount) {
        return 1.0;
    }
    const DdgiVolumeInfo volume = gDdgi.volumes[v];
    const float3 grid = (p - volume.origin) / volume.spacing;
    const float3 last = float3(volume.counts) - 1.0;
    // Cells from the lattice's edge: negative inside; 0.5 at the grown box's edge.
    const float3 outside = max(-grid, grid - last);
    const float worst = max(outside.x, max(outside.y, outside.z));
    return saturate(1.0 - 2.0 * worst);
}

[numthreads(LUMINA_DDGI_SAMPLE_GROUP, LUMINA_DDGI_SAMPLE_GROUP, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gDdgi.imageSize.x || id.y >= gDdgi.imageSize.y) {
        return;
    }
    const float4 normal = gNormal.Load(int3(id.xy, 0));
    const float4 position = gPosition.Load(int3(id.xy, 0));
    if (normal.w <= 0.0 || position.w <= 0.0) {
        gOut[id.xy] = float4(0.0, 0.0, 0.0, 0.0);
        return;
    }
    const float3 n = normalize(normal.xyz);
    const float3 p = position.xyz;
    const float3 towardsCamera = normalize(gDdgi.cameraPosition - p);
    float3 irradiance = float3(0.0, 0.0, 0.0);
    float remaining = 1.0;
    for (uint v = 0u; v < gDdgi.volumeCount && remaining > 0.0; ++v) {
        const float coverage = volumeCoverage(v, p);
        if (coverage <= 0.0) {
            continue;
        }
        const float4 e = sampleVolume(v, p, n, towardsCamera);
        if (e.a > 0.0) {
            irradiance += remaining * coverage * e.rgb / e.a;
            remaining *= 1.0 - coverage;
        }
    }
    gOut[id.xy] = float4(ddgiSanitise(irradiance / max(1.0 - remaining, LUMINA_DDGI_MIN_WEIGHT)), 1.0);
}
