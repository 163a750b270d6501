// lumina-kernel: cs main
// Pass 7, composite: the rays of a probe into its 8 x 8 hemi-octahedral radiance map. Each texel
// keeps the MIS-weighted mean of the radiance of the rays that landed in it, sum(w L) / sum(w),
// and that weight normalised by the texel's solid angle (its expected value is 1: the weights are
// 1 / density), so the temporal pass can accumulate numerator and denominator across frames.
// Texels no ray reached this frame have weight 0. Non-finite rays are dropped here.
// One group per probe, one thread per texel.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<ProbeRay> gRays : register(t1);
StructuredBuffer<float4> gRayRadiance : register(t2);
RWStructuredBuffer<float4> gRadiance : register(u0); // per texel: rgb mean radiance; a: weight / solid angle

// The probe's rays, loaded once by the group (every texel thread scans all of them): rgb weight x
// radiance, a weight (0 for a dropped ray); and the texel each landed in.
groupshared float4 gsRays[LUMINA_SP_MAX_RAYS];
groupshared uint gsTexels[LUMINA_SP_MAX_RAYS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const uint rayCount = gSp.raysPerProbe;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const ProbeRay ray = gRays[probe * rayCount + r];
        const float3 radiance = gRayRadiance[probe * rayCount + r].rgb;
        const float w = ray.directionAndWeight.w;
        const bool usable = allFinite3(radiance) && w > 0.0 && !isinf(w);
        gsRays[r] = usable ? float4(w * radiance, w) : float4(0.0, 0.0, 0.0, 0.0);
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
    const float solidAngle = texelSolidAngle(t);
    gRadiance[probe * LUMINA_SP_PROBE_TEXELS + t] =
        weight > 0.0 ? float4(sum / weight, weight / solidAngle) : float4(0.0, 0.0, 0.0, 0.0);
}
