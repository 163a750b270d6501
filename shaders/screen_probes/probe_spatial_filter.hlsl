// lumina-kernel: cs main
// Pass 9, spatial filter: each texel of a probe's accumulated radiance averaged with the same
// world direction in its four grid neighbours (a cross-bilateral filter over the probe grid; an
// adaptive probe takes the uniform probes of its cell and that cell's four neighbours). The
// centre weighs 1; a neighbour exp(-plane distance / (filterPlaneScale x view depth)) x
// max(0, n . n')^filterNormalPower, so light does not bleed across depth or orientation edges. Texels with
// no data (weight 0) take no part. One group per probe, one thread per texel.
//
// The neighbours' weights fade as the probe's history grows: times (1 - probeHistoryBlend)^age, the
// share of a converged history's weight that the probe's own still lacks (age: the frames of
// history it continues, probe_temporal.hlsl). A new or disoccluded probe is filtered in full; a
// probe with a long history keeps its own light. Unfaded, the filter averaged probes that see
// different things: behind a doorway's jamb, a floor probe whose history gave an irradiance of 1.8
// read 3.8 filtered, from its neighbour in the doorway (10.0), which sees the lit room's ceiling
// panel (`two_rooms`, 128 x 128, low: relMSE 0.048 filtered, 0.025 unfiltered, after convergence).
// Once converged, a probe's own texels were less noisy than the filter was biased in every
// built-in scene (docs/gi.md, energy 27.). A texel with no data of its own still takes its
// neighbours' in full.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<float4> gHistory : register(t1);
StructuredBuffer<uint> gProbeAge : register(t2);     // probe_temporal's ages this frame
RWStructuredBuffer<float4> gFiltered : register(u0); // rgb: radiance; a: 1 where any sample had data

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    // Read first: loaded later, into a register whose other lanes held the direction, the age
    // scrambled the filtered map on D3D12 under Wine (docs/d3d12.md, "The frame on D3D12 under Wine").
    const uint age = gProbeAge[probe];
    const ScreenProbe centre = gProbes[probe];
    const float3 direction = texelDirection(probeFrame(centre.normal.xyz), t);
    const float4 own = gHistory[probe * LUMINA_SP_PROBE_TEXELS + t];
    float3 sum = own.a > 0.0 ? own.rgb : float3(0.0, 0.0, 0.0);
    float weight = own.a > 0.0 ? 1.0 : 0.0;
    const float youth = own.a > 0.0 && age > 0u ? exp2(float(age) * log2(1.0 - gSp.probeHistoryBlend)) : 1.0;
    // An adaptive probe's neighbours are the uniform probe of the cell it lies in and that cell's four.
    const int2 offsets[5] = {int2(0, 0), int2(-1, 0), int2(1, 0), int2(0, -1), int2(0, 1)};
    const bool adaptive = isAdaptiveProbe(probe);
    const int2 cell = adaptive ? int2(centre.info.yz / gSp.probeSpacing) : int2(group.xy);
    for (uint k = adaptive ? 0u : 1u; k < 5u; ++k) {
        const int2 at = cell + offsets[k];
        if (any(at < 0) || any(at >= int2(gSp.probeGrid))) {
            continue;
        }
        const uint other = uint(at.y) * gSp.probeGrid.x + uint(at.x);
        const ScreenProbe neighbour = gProbes[other];
        if (!probeIsValid(neighbour)) {
            continue;
        }
        const float3 offset = neighbour.positionAndDepth.xyz - centre.positionAndDepth.xyz;
        const float planeDistance = abs(dot(offset, centre.normal.xyz));
        const float w = youth * exp(-planeDistance / (gSp.filterPlaneScale * centre.positionAndDepth.w)) *
                        pow(saturate(dot(neighbour.normal.xyz, centre.normal.xyz)), gSp.filterNormalPower);
        const int texel = texelInFrame(probeFrame(neighbour.normal.xyz), direction);
        if (texel < 0 || !(w > 0.0)) {
            continue;
        }
        const float4 value = gHistory[other * LUMINA_SP_PROBE_TEXELS + uint(texel)];
        if (value.a > 0.0) {
            sum += w * value.rgb;
            weight += w;
        }
    }
    gFiltered[probe * LUMINA_SP_PROBE_TEXELS + t] =
        weight > 0.0 ? float4(sum / weight, 1.0) : float4(0.0, 0.0, 0.0, 0.0);
}
