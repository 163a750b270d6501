#ifndef LUMINA_SP_PROBE_HISTORY_HLSLI
#define LUMINA_SP_PROBE_HISTORY_HLSLI
// Reading a probe's radiance history from the previous frame, for the lighting PDF and the
// temporal pass. The includer declares, before including this file:
//
//   StructuredBuffer<ScreenProbe> gPreviousProbes;   // last frame's probes
//   StructuredBuffer<float4> gPreviousHistory;       // probe_temporal's output of last frame
#include "screen_probes/screen_probe_common.hlsli"

// The old probe whose history `current` continues: the one its position reprojects to, if it saw
// the same surface (historyMatches); else -1.
int historyProbe(ScreenProbe current) {
    const int candidate = historyProbeCandidate(current.positionAndDepth.xyz);
    return candidate >= 0 && historyMatches(current, gPreviousProbes[candidate]) ? candidate : -1;
}

// Texel t of the history of `current` (frame f): historyProbe's, looked up in the same world
// direction. Zero (weight 0) where there is none: no history, a probe that moved, a direction below
// the old probe's plane.
float4 historyTexel(ScreenProbe current, ProbeFrame f, uint t) {
    const int candidate = historyProbe(current);
    if (candidate < 0) {
        return float4(0.0, 0.0, 0.0, 0.0);
    }
    const int texel = texelInFrame(probeFrame(gPreviousProbes[candidate].normal.xyz), texelDirection(f, t));
    return texel >= 0 ? gPreviousHistory[uint(candidate) * LUMINA_SP_PROBE_TEXELS + uint(texel)]
                      : float4(0.0, 0.0, 0.0, 0.0);
}

#endif
