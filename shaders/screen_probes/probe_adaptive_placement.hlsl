// lumina-kernel: cs main
// Pass 1b, adaptive placement: probes where the uniform grid has none on a pixel's surface. The image
// is cut into adaptive tiles of adaptiveSpacing (half the probe spacing) pixels a side; in each, the
// surface pixel whose best corner probe weighs least (probeSurfaceWeight, the gather's weight) is
// found, and if that weight is below LUMINA_SP_ADAPTIVE_COVERAGE the tile takes a slot in the
// adaptive rows and places a probe at that pixel. Such pixels lie on a surface no cell centre saw: a
// strip of wall between a doorway's jamb and an open door, a thin object, a silhouette whose cell
// centres see the sky. Without them the gather reads probes on other surfaces there (the door's 6 cm
// strip was 90 % of lumen's error at 256 x 256; docs/gi.md, energy 45.).
//
// Slots are taken in whatever order the threads run, so which slot a tile gets varies; nothing reads
// a probe by its slot number except through gAdaptiveIndex, and every later pass treats a probe by
// its position (ray directions are seeded by its pixel), so the image does not depend on the order.
// When the rows are full, the tiles left over get none. One thread per adaptive tile.
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
RWStructuredBuffer<ScreenProbe> gProbes : register(u0);  // reads the uniform grid's, writes adaptive slots
RWStructuredBuffer<uint> gAdaptiveCount : register(u1); // [0]: slots taken (zeroed by the placement pass)
// Per tile: its probe's slot or LUMINA_SP_NO_ADAPTIVE_PROBE.
RWStructuredBuffer<uint> gAdaptiveIndex : register(u2);

// The best surface weight among the valid uniform probes at the corners of the pixel's cell (0: none
// valid).
float uniformCoverage(uint2 pixel, float4 position, float3 n) {
    float best = 0.0;
    for (uint k = 0u; k < 4u; ++k) {
        float bilinear;
        const ScreenProbe p = gProbes[uniformCorner(pixel, k, bilinear)];
        if (probeIsValid(p)) {
            best = max(best, probeSurfaceWeight(p, position, n));
        }
    }
    return best;
}

[numthreads(LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint2 tiles = adaptiveGrid();
    if (any(id.xy >= tiles)) {
        return;
    }
    const uint spacing = gSp.adaptiveSpacing;
    float worst = LUMINA_SP_ADAPTIVE_COVERAGE;
    bool found = false;
    uint2 worstPixel = uint2(0u, 0u);
    float4 worstPosition = float4(0.0, 0.0, 0.0, 0.0);
    float3 worstNormal = float3(0.0, 0.0, 1.0);
    for (uint i = 0u; i < spacing * spacing; ++i) {
        const uint2 pixel = id.xy * spacing + uint2(i % spacing, i / spacing);
        const bool inside = all(pixel < gSp.imageSize);
        const float4 normal = inside ? gNormal.Load(int3(pixel, 0)) : float4(0.0, 0.0, 0.0, 0.0);
        const float4 position = inside ? gPosition.Load(int3(pixel, 0)) : float4(0.0, 0.0, 0.0, 0.0);
        const float normalLength = length(normal.xyz);
        const bool surface = normal.w > 0.0 && position.w > 0.0 && normalLength > 0.0 &&
                             allFinite3(position.xyz) && allFinite3(normal.xyz);
        if (surface) {
            const float3 n = normal.xyz / normalLength;
            const float coverage = uniformCoverage(pixel, position, n);
            if (coverage < worst) {
                worst = coverage;
                found = true;
                worstPixel = pixel;
                worstPosition = position;
                worstNormal = n;
            }
        }
    }
    uint slot = LUMINA_SP_NO_ADAPTIVE_PROBE;
    if (found) {
        uint taken;
        InterlockedAdd(gAdaptiveCount[0], 1u, taken);
        if (taken < gSp.probeCount - gSp.uniformProbeCount) {
            slot = gSp.uniformProbeCount + taken;
            ScreenProbe probe;
            probe.positionAndDepth = worstPosition;
            probe.normal = float4(worstNormal, 0.0);
            probe.info = uint4(LUMINA_SP_PROBE_VALID, worstPixel, 0u);
            gProbes[slot] = probe;
        }
    }
    gAdaptiveIndex[id.y * tiles.x + id.x] = slot;
}
