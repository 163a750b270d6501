// lumina-kernel: cs main
// Pass 2, BRDF PDF: the cosine-weighted hemisphere around the probe normal (Lambert), as the
// probability of each texel of the probe's hemi-octahedral map. In the probe's own frame the
// table is the same for every probe; it is still written per probe so that a BRDF made from the
// pixels around the probe (SimLumen's SH of neighbouring normals) can replace it without
// touching the sampler. One group per probe, one thread per texel.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
RWStructuredBuffer<float> gBrdfPdf : register(u0); // LUMINA_SP_PROBE_TEXELS per probe, summing to 1

groupshared float gsMass[LUMINA_SP_PROBE_TEXELS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return; // uniform across the group: the barrier below is reached by all or none
    }
    gsMass[t] = hemiOctTexelCosineMass(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
    GroupMemoryBarrierWithGroupSync();
    // Normalise the quadrature (off from 1 by about 1e-4) so the table is a distribution.
    float total = 0.0;
    for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
        total += gsMass[i];
    }
    gBrdfPdf[probe * LUMINA_SP_PROBE_TEXELS + t] = gsMass[t] / total;
}
