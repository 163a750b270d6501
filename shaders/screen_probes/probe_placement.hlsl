// lumina-kernel: cs main
// Pass 1, placement: one probe per spacing x spacing cell, at the GBuffer surface seen by the
// cell's centre pixel (position, view depth, normal). Cells whose centre sees the sky get an
// invalid probe, which every later pass skips. The adaptive rows below the grid are emptied: only
// the slots the adaptive allocation fills this frame hold probes. One thread per probe slot.
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);   // xyz: unit world normal; a = 1 on surfaces
Texture2D<float4> gPosition : register(t1); // xyz: world position; w: view depth (0: background)
RWStructuredBuffer<ScreenProbe> gProbes : register(u0);

[numthreads(LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint slot = id.y * gSp.probeGrid.x + id.x;
    if (id.x >= gSp.probeGrid.x || slot >= gSp.probeCount) {
        return;
    }
    const uint spacing = gSp.probeSpacing;
    const uint2 pixel = min(id.xy * spacing + spacing / 2u, gSp.imageSize - 1u);
    const float4 normal = gNormal.Load(int3(pixel, 0));
    const float4 position = gPosition.Load(int3(pixel, 0));
    const float normalLength = length(normal.xyz);
    const bool surface = !isAdaptiveProbe(slot) && normal.w > 0.0 && position.w > 0.0 &&
                         normalLength > 0.0 && allFinite3(position.xyz) && allFinite3(normal.xyz);
    ScreenProbe probe;
    probe.positionAndDepth = surface ? position : float4(0.0, 0.0, 0.0, 0.0);
    probe.normal = surface ? float4(normal.xyz / normalLength, 0.0) : float4(0.0, 0.0, 1.0, 0.0);
    const uint2 at = isAdaptiveProbe(slot) ? uint2(0u, 0u) : pixel;
    probe.info = uint4(surface ? LUMINA_SP_PROBE_VALID : 0u, at, 0u);
    gProbes[slot] = probe;
}
