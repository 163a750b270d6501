#ifndef LUMINA_SP_PROBE_HISTORY_HLSLI
#define LUMINA_SP_PROBE_HISTORY_HLSLI
// Reading a probe's radiance history from the previous frame, for the lighting PDF and the
// temporal pass. The includer declares, before including this file:
//
//   StructuredBuffer<ScreenProbe> gPreviousProbes;   // last frame's probes
//   StructuredBuffer<float4> gPreviousHistory;       // probe_temporal's output of last frame
//   StructuredBuffer<uint> gPreviousAdaptiveIndex;   // probe_adaptive_placement's index of last frame
#include "screen_probes/screen_probe_common.hlsli"

// The uniform probe of the cell `current`'s position reprojects to last frame, if it saw the same
// surface (historyMatches); else -1.
int uniformHistoryProbe(ScreenProbe current) {
    const int candidate = historyProbeCandidate(current.positionAndDepth.xyz);
    return candidate >= 0 && historyMatches(current, gPreviousProbes[candidate]) ? candidate : -1;
}

// The adaptive probe of the adaptive tile `current`'s position reprojects to last frame, if it saw
// the same surface; else -1.
int adaptiveHistoryProbe(ScreenProbe current) {
    float2 pixel;
    if (gSp.adaptiveSpacing == 0u || !hasFlag(LUMINA_SP_FLAG_PROBE_HISTORY) ||
        !previousPixel(current.positionAndDepth.xyz, pixel)) {
        return -1;
    }
    const uint2 tiles = adaptiveGrid();
    const uint2 tile = min(uint2(pixel) / gSp.adaptiveSpacing, tiles - 1u);
    const uint old = gPreviousAdaptiveIndex[tile.y * tiles.x + tile.x];
    const bool matches = old != LUMINA_SP_NO_ADAPTIVE_PROBE && historyMatches(current, gPreviousProbes[old]);
    return matches ? int(old) : -1;
}

// The old probe whose history `current` (in slot `probe`) continues: a uniform probe looks first
// among last frame's uniform probes, an adaptive one among the adaptive ones (its surface is one no
// uniform probe saw), and each then in the other kind; -1 when neither saw its surface.
int historyProbe(ScreenProbe current, uint probe) {
    const bool adaptive = isAdaptiveProbe(probe);
    const int first = adaptive ? adaptiveHistoryProbe(current) : uniformHistoryProbe(current);
    if (first >= 0) {
        return first;
    }
    return adaptive ? uniformHistoryProbe(current) : adaptiveHistoryProbe(current);
}

// Where texel t of the history of `current` (slot `probe`, frame f) lies in last frame's buffers:
// historyProbe's texel in the same world direction; -1 where there is none (no history, a probe
// that moved, a direction below the old probe's plane).
int historyTexelIndex(ScreenProbe current, uint probe, ProbeFrame f, uint t) {
    const int candidate = historyProbe(current, probe);
    if (candidate < 0) {
        return -1;
    }
    const int texel = texelInFrame(probeFrame(gPreviousProbes[candidate].normal.xyz), texelDirection(f, t));
    return texel >= 0 ? candidate * int(LUMINA_SP_PROBE_TEXELS) + texel : -1;
}

// That texel's radiance history; zero (weight 0) where there is none.
float4 historyTexel(ScreenProbe current, uint probe, ProbeFrame f, uint t) {
    const int index = historyTexelIndex(current, probe, f, t);
    return index >= 0 ? gPreviousHistory[uint(index)] : float4(0.0, 0.0, 0.0, 0.0);
}

#endif
