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

// Where texel t of the history of `current` (frame f) lies in last frame's buffers: historyProbe's
// texel in the same world direction; -1 where there is none (no history, a probe that moved, a
// direction below the old probe's plane).
int historyTexelIndex(ScreenProbe current, ProbeFrame f, uint t) {
    const int candidate = historyProbe(current);
    if (candidate < 0) {
        return -1;
    }
    const int texel = texelInFrame(probeFrame(gPreviousProbes[candidate].normal.xyz), texelDirection(f, t));
    return texel >= 0 ? candidate * int(LUMINA_SP_PROBE_TEXELS) + texel : -1;
}

// That texel's radiance history; zero (weight 0) where there is none.
float4 historyTexel(ScreenProbe current, ProbeFrame f, uint t) {
    const int index = historyTexelIndex(current, f, t);
    return index >= 0 ? gPreviousHistory[uint(index)] : float4(0.0, 0.0, 0.0, 0.0);
}

#endif
