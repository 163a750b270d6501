// lumina-kernel: cs main
// Pass 4, MIS directions: rays.y rays from the BRDF table and rays.z from the lighting table,
// each a low-discrepancy point (Hammersley, rotated per frame and per probe) warped through its
// table, carrying the balance-heuristic weight 1 / (nBrdf p_b + nLight p_l)
// (probe_sampling_shared.h). One group per probe; thread t makes rays t, t + 64, ...
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<float> gBrdfPdf : register(t1);
StructuredBuffer<float> gLightingPdf : register(t2);
RWStructuredBuffer<ProbeRay> gRays : register(u0); // rays.x per probe

groupshared float gsBrdf[LUMINA_SP_PROBE_TEXELS];
groupshared float gsLight[LUMINA_SP_PROBE_TEXELS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.grid.w || !probeIsValid(gProbes[probe])) {
        return;
    }
    gsBrdf[t] = gBrdfPdf[probe * LUMINA_SP_PROBE_TEXELS + t];
    gsLight[t] = gLightingPdf[probe * LUMINA_SP_PROBE_TEXELS + t];
    GroupMemoryBarrierWithGroupSync();
    SpTexelTable brdf;
    SpTexelTable light;
    for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS / 4u; ++i) {
        brdf.p[i] = float4(gsBrdf[4u * i], gsBrdf[4u * i + 1u], gsBrdf[4u * i + 2u], gsBrdf[4u * i + 3u]);
        light.p[i] = float4(gsLight[4u * i], gsLight[4u * i + 1u], gsLight[4u * i + 2u], gsLight[4u * i + 3u]);
    }
    const ProbeFrame frame = probeFrame(gProbes[probe].normal.xyz);
    const uint rayCount = gSp.rays.x;
    const uint brdfRays = gSp.rays.y;
    const float nBrdf = float(brdfRays);
    const float nLight = float(gSp.rays.z);
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const bool fromBrdf = r < brdfRays;
        const uint strategy = fromBrdf ? LUMINA_SP_STRATEGY_BRDF : LUMINA_SP_STRATEGY_LIGHTING;
        const uint local = fromBrdf ? r : r - brdfRays;
        const uint count = fromBrdf ? brdfRays : gSp.rays.z;
        const float2 u = spSamplePoint(local, count, gSp.screen.z, probe, strategy);
        SpTableSample s; // if/else, not ?: on structs, which HLSL 2021 (DXC) does not take
        if (fromBrdf) {
            s = spSampleTable(brdf, u);
        } else {
            s = spSampleTable(light, u);
        }
        const float pBrdf = spTableDensity(gsBrdf[s.texel], s.e, LUMINA_SP_OCT_SIZE);
        const float pLight = spTableDensity(gsLight[s.texel], s.e, LUMINA_SP_OCT_SIZE);
        ProbeRay ray;
        ray.directionAndWeight = float4(probeToWorld(frame, hemiOctDecode(s.e)), spMisWeight(nBrdf, pBrdf, nLight, pLight));
        ray.info = uint4(s.texel, strategy, 1u, 0u);
        gRays[probe * rayCount + r] = ray;
    }
}
