// lumina-kernel: cs main
// Pass 7, composite: the rays of a probe into its 8 x 8 hemi-octahedral radiance map. Each texel
// keeps the cosine-weighted mean of the radiance of the rays that landed in it, sum(w cos L) /
// sum(w cos) with w the MIS weight, and that weight normalised by the texel's cosine integral (its
// expected value is 1: the weights are 1 / density), so the temporal pass can accumulate numerator
// and denominator across frames. Texels no ray reached this frame have weight 0. Non-finite rays
// are dropped here.
//
// Why cosine-weighted: the irradiance a texel gives is its value times the integral of cos over
// it, and near the horizon a texel spans cos(theta) from 0 to a third. A plain mean radiance
// spreads a source that sits low in its texel over the whole texel: a ceiling light seen at
// grazing angles from a vertical face counted 1.8 times its irradiance (docs/gi.md, energy 24.).
// The cosine-weighted mean makes the map's irradiance at the probe's normal the rays' own estimate
// of it, and a uniform radiance still gives itself exactly.
// One group per probe, one thread per texel.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<ProbeRay> gRays : register(t1);
StructuredBuffer<float4> gRayRadiance : register(t2);
RWStructuredBuffer<float4> gRadiance : register(u0); // per texel: rgb cosine-weighted mean radiance; a: weight / cosine integral

// The probe's rays, loaded once by the group (every texel thread scans all of them): rgb weight x
// cos x radiance, a weight x cos (0 for a dropped ray); and the texel each landed in.
groupshared float4 gsRays[LUMINA_SP_MAX_RAYS];
groupshared uint gsTexels[LUMINA_SP_MAX_RAYS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const uint rayCount = gSp.raysPerProbe;
    const float3 normal = gProbes[probe].normal.xyz;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const ProbeRay ray = gRays[probe * rayCount + r];
        const float3 radiance = gRayRadiance[probe * rayCount + r].rgb;
        const float w = ray.directionAndWeight.w;
        const float cosine = max(dot(ray.directionAndWeight.xyz, normal), 0.0);
        const bool usable = allFinite3(radiance) && w > 0.0 && !isinf(w);
        gsRays[r] = usable ? float4(w * cosine * radiance, w * cosine) : float4(0.0, 0.0, 0.0, 0.0);
        gsTexels[r] = ray.info.x;
    }
    GroupMemoryBarrierWithGroupSync();
    float3 sum = float3(0.0, 0.0, 0.0);
    float weight = 0.0;
    for (uint i = 0u; i < rayCount; ++i) {
        if (gsTexels[i] == t) {
            sum += gsRays[i].rgb;
            weight += gsRays[i].a;
        }
    }
    const float cosineIntegral = LUMINA_PI * texelCosineMass(t);
    gRadiance[probe * LUMINA_SP_PROBE_TEXELS + t] =
        weight > 0.0 ? float4(sum / weight, weight / cosineIntegral) : float4(0.0, 0.0, 0.0, 0.0);
}
