// lumina-kernel: cs main
// Pass 4, MIS directions: brdfRays rays from the BRDF table and lightingRays from the lighting table,
// each a low-discrepancy point (Hammersley, rotated per frame and per probe) warped through its
// table, carrying the balance-heuristic weight 1 / (nBrdf p_b + nLight p_l)
// (probe_sampling_shared.h). One group per probe; thread t makes rays t, t + 64, ...
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<float> gBrdfPdf : register(t1);
StructuredBuffer<float> gLightingPdf : register(t2);
RWStructuredBuffer<ProbeRay> gRays : register(u0); // raysPerProbe per probe

groupshared float gsBrdf[LUMINA_SP_PROBE_TEXELS];
groupshared float gsLight[LUMINA_SP_PROBE_TEXELS];
// Prefix sums: entry k is the probability of texels 0 .. k - 1 (entry 0 is 0).
groupshared float gsBrdfCdf[LUMINA_SP_PROBE_TEXELS + 1u];
groupshared float gsLightCdf[LUMINA_SP_PROBE_TEXELS + 1u];

// The last texel whose CDF start is at most u (texels of probability 0 share their start with
// the next, so they are passed over), by bisection over the prefix sums.
uint findTexel(bool brdf, float u) {
    uint lo = 0u;
    uint hi = LUMINA_SP_PROBE_TEXELS - 1u;
    while (lo < hi) {
        const uint mid = (lo + hi + 1u) / 2u;
        if ((brdf ? gsBrdfCdf[mid] : gsLightCdf[mid]) <= u) {
            lo = mid;
        } else {
            hi = mid - 1u;
        }
    }
    return lo;
}

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    gsBrdf[t] = gBrdfPdf[probe * LUMINA_SP_PROBE_TEXELS + t];
    gsLight[t] = gLightingPdf[probe * LUMINA_SP_PROBE_TEXELS + t];
    GroupMemoryBarrierWithGroupSync();
    if (t == 0u) { // 2 x 64 adds, in the order the CPU reference adds them
        gsBrdfCdf[0] = 0.0;
        gsLightCdf[0] = 0.0;
        for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
            gsBrdfCdf[i + 1u] = gsBrdfCdf[i] + gsBrdf[i];
            gsLightCdf[i + 1u] = gsLightCdf[i] + gsLight[i];
        }
    }
    GroupMemoryBarrierWithGroupSync();
    const ProbeFrame frame = probeFrame(gProbes[probe].normal.xyz);
    const uint seed = spProbeSeed(probe, gSp.uniformProbeCount, gProbes[probe].info.yz, gSp.imageSize.x);
    const uint rayCount = gSp.raysPerProbe;
    const uint brdfRays = gSp.brdfRays;
    const float nBrdf = float(brdfRays);
    const float nLight = float(gSp.lightingRays);
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const bool fromBrdf = r < brdfRays;
        const uint strategy = fromBrdf ? LUMINA_SP_STRATEGY_BRDF : LUMINA_SP_STRATEGY_LIGHTING;
        const uint local = fromBrdf ? r : r - brdfRays;
        const uint count = fromBrdf ? brdfRays : gSp.lightingRays;
        const float2 u = spSamplePoint(local, count, gSp.frameIndex, seed, strategy);
        const uint k = findTexel(fromBrdf, u.x);
        const float before = fromBrdf ? gsBrdfCdf[k] : gsLightCdf[k];
        const SpTableSample s = spTableSampleAt(k, before, fromBrdf ? gsBrdf[k] : gsLight[k], u);
        const float pBrdf = spTableDensity(gsBrdf[s.texel], s.e, LUMINA_SP_OCT_SIZE);
        const float pLight = spTableDensity(gsLight[s.texel], s.e, LUMINA_SP_OCT_SIZE);
        ProbeRay ray;
        const float3 direction = probeToWorld(frame, hemiOctDecode(s.e));
        ray.directionAndWeight = float4(direction, spMisWeight(nBrdf, pBrdf, nLight, pLight));
        ray.info = uint4(s.texel, strategy, 1u, 0u);
        gRays[probe * rayCount + r] = ray;
    }
}
