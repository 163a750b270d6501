// lumina-kernel: cs main
// Pass 8, temporal accumulation of probe radiance. The history texel is found like the lighting PDF's
// (reprojected probe, same surface, same world direction); a probe that moved loses it. Numerator and
// denominator of each texel's weighted mean are blended exponentially,
//     W' = (1 - a) W + a w,   L' = ((1 - a) W L + a w x) / W'   (a = probeHistoryBlend, about 10% new),
// so early frames average like a running mean and texels no ray reached keep their radiance. A new value
// brighter than outlierClamp x max(the preset's share of the texel's unclamped mean, the probe's mean of
// them) is scaled down to that (a single bright ray must not linger for ten frames; with k > 1 rays a texel
// the factor is 1 + (outlierClamp - 1) / k, the same bound on one ray). The unclamped mean is the same
// weighted mean of the values before the clamp, kept beside the history: a ceiling made from the clamped
// history itself rises only with what it lets in, so a texel that once read dark kept clamping light that one
// that read bright let in, for good (docs/screen_probes.md). The factor trades bias for steadiness: a light
// smaller than a texel reads several times its texel's mean every frame a ray hits it, so 2 took a quarter of
// the Cornell box floor's light; clamping against the probe's brightest texel instead kept all of it but let
// the image flicker ten times more. L' is a convex combination of inputs, so accumulation never exceeds the
// largest input; non-finite results are written as empty texels, so NaN and Inf never enter history. The
// probe's age, the frames of history it continues (0 for a new probe, scaled down with the weight a change
// region takes away), goes to gProbeAge for the spatial filter. One group per probe, one thread per texel.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<ScreenProbe> gPreviousProbes : register(t1);
StructuredBuffer<float4> gFrameRadiance : register(t2);   // probe_composite's output
StructuredBuffer<float4> gPreviousHistory : register(t3); // this pass's output last frame
StructuredBuffer<uint> gPreviousProbeAge : register(t4);  // this pass's ages last frame
StructuredBuffer<float> gPreviousUnclamped : register(t5); // this pass's unclamped means last frame
StructuredBuffer<uint> gPreviousAdaptiveIndex : register(t6); // last frame's adaptive tiles' probes
RWStructuredBuffer<float4> gHistory : register(u0);
RWStructuredBuffer<uint> gProbeAge : register(u1);
RWStructuredBuffer<float> gUnclamped : register(u2); // luminance mean of the values before the clamp
#include "screen_probes/probe_history.hlsli"

groupshared float gsLuminance[LUMINA_SP_PROBE_TEXELS];
groupshared float gsSolidAngle[LUMINA_SP_PROBE_TEXELS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const ScreenProbe current = gProbes[probe];
    const ProbeFrame frame = probeFrame(current.normal.xyz);
    const int historyIndex = historyTexelIndex(current, probe, frame, t);
    const float4 history =
        historyIndex >= 0 ? gPreviousHistory[uint(historyIndex)] : float4(0.0, 0.0, 0.0, 0.0);
    // Read only beside a history texel this pass wrote (weight > 0), which it wrote with it.
    const float unclamped = history.a > 0.0 ? gPreviousUnclamped[uint(historyIndex)] : 0.0;
    const float keep = historyKeep(current.positionAndDepth.xyz);
    if (t == 0u) {
        const int previous = historyProbe(current, probe);
        gProbeAge[probe] =
            previous < 0 ? 0u
                         : min(uint(float(gPreviousProbeAge[previous]) * keep) + 1u, LUMINA_SP_MAX_PROBE_AGE);
    }
    const float solidAngle = texelSolidAngle(t);
    gsLuminance[t] = history.a > 0.0 ? unclamped * solidAngle : 0.0;
    gsSolidAngle[t] = history.a > 0.0 ? solidAngle : 0.0;
    GroupMemoryBarrierWithGroupSync();
    float meanLuminance = 0.0;
    float covered = 0.0;
    for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
        meanLuminance += gsLuminance[i];
        covered += gsSolidAngle[i];
    }
    meanLuminance = covered > 0.0 ? meanLuminance / covered : 0.0;

    float4 x = gFrameRadiance[probe * LUMINA_SP_PROBE_TEXELS + t];
    if (!allFinite3(x.rgb) || !(x.a >= 0.0) || isinf(x.a)) {
        x = float4(0.0, 0.0, 0.0, 0.0);
    }
    // Outlier clamp: relative to the probe's own light level; a probe with no (or black) history
    // has nothing to call an outlier against. A texel averages k = rays / texels rays, so one ray
    // moves it by 1/k of its excess: the factor bounds that one ray's excess to (outlierClamp - 1)
    // whatever k is. With a fixed factor, high (2 rays a texel) kept light that low and medium
    // clamp, and was less accurate than medium (docs/gi.md, energy 36.).
    const float raysPerTexel = max(float(gSp.raysPerProbe) / float(LUMINA_SP_PROBE_TEXELS), 1.0);
    const float factor = 1.0 + (gSp.outlierClamp - 1.0) / raysPerTexel;
    const float limit = factor * max(gSp.outlierClampTexelShare * unclamped, meanLuminance);
    const float l = luminance(x.rgb);
    const float lUnclamped = limit > 0.0 ? min(l, LUMINA_SP_UNCLAMPED_CAP * limit) : l;
    if (limit > 0.0 && l > limit) {
        x.rgb *= limit / l;
    }
    const float a = gSp.probeHistoryBlend;
    // Where the scene changed, the old light is (partly) wrong: it keeps less weight.
    const float oldWeight = (1.0 - a) * history.a * keep;
    const float newWeight = a * x.a;
    const float weight = oldWeight + newWeight;
    float4 result = weight > 0.0 ? float4((oldWeight * history.rgb + newWeight * x.rgb) / weight, weight)
                                 : float4(history.rgb, 0.0);
    float unclampedResult =
        weight > 0.0 ? (oldWeight * unclamped + newWeight * lUnclamped) / weight : unclamped;
    if (!allFinite3(result.rgb) || !(result.a >= 0.0) || isinf(result.a)) {
        result = float4(0.0, 0.0, 0.0, 0.0);
    }
    if (!allFinite3(unclampedResult.xxx)) {
        unclampedResult = luminance(result.rgb);
    }
    gHistory[probe * LUMINA_SP_PROBE_TEXELS + t] = result;
    gUnclamped[probe * LUMINA_SP_PROBE_TEXELS + t] = unclampedResult;
}
