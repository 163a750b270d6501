// lumina-kernel: cs main
// Pass 3, lighting PDF: where light came from last frame. The probe is reprojected into the
// previous frame and, where the old probe there saw the same surface, each texel's direction is
// looked up in the old probe's radiance history: texel probability ~ luminance x solid angle. A
// floor (lightingPdfFloor) of the distribution is spread uniformly over the hemisphere so that every
// direction stays reachable; without history the table is uniform in solid angle.
// One group per probe, one thread per texel.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<ScreenProbe> gPreviousProbes : register(t1);
StructuredBuffer<float4> gPreviousHistory : register(t2); // probe_temporal's output of last frame
StructuredBuffer<uint> gPreviousAdaptiveIndex : register(t3); // last frame's adaptive tiles' probes
RWStructuredBuffer<float> gLightingPdf : register(u0);   // LUMINA_SP_PROBE_TEXELS per probe, summing to 1
#include "screen_probes/probe_history.hlsli"

groupshared float gsMass[LUMINA_SP_PROBE_TEXELS];
groupshared float gsSolidAngle[LUMINA_SP_PROBE_TEXELS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const ScreenProbe current = gProbes[probe];
    const ProbeFrame frame = probeFrame(current.normal.xyz);
    const float solidAngle = texelSolidAngle(t);

    const float4 radiance = historyTexel(current, probe, frame, t);
    const float l = spLightingPdfLuminance(luminance(radiance.rgb));
    // History is sanitised when written; the check keeps a bad table from sampling nothing.
    const float mass = radiance.a > 0.0 && l > 0.0 && !isinf(l) ? l * solidAngle : 0.0;
    gsMass[t] = mass;
    gsSolidAngle[t] = solidAngle;
    GroupMemoryBarrierWithGroupSync();
    float totalMass = 0.0;
    float totalSolidAngle = 0.0;
    for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
        totalMass += gsMass[i];
        totalSolidAngle += gsSolidAngle[i];
    }
    const float even = solidAngle / totalSolidAngle;
    const float floorShare = gSp.lightingPdfFloor;
    const float p = totalMass > 0.0 ? (1.0 - floorShare) * mass / totalMass + floorShare * even : even;
    gLightingPdf[probe * LUMINA_SP_PROBE_TEXELS + t] = p;
}
