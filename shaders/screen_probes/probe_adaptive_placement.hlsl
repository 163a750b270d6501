// lumina-kernel: cs main
// Pass 1b, adaptive placement: where adaptive probes are wanted. The image is cut into adaptive
// tiles of adaptiveSpacing (half the probe spacing) pixels a side; in each, the surface pixel whose
// best corner probe weighs least (probeSurfaceWeight, the gather's weight) is found, and if that
// weight is below LUMINA_SP_ADAPTIVE_COVERAGE the tile wants a probe at that pixel. Such pixels lie
// on a surface no cell centre saw: a strip of wall between a doorway's jamb and an open door, a thin
// object, a silhouette whose cell centres see the sky. Without them the gather reads probes on other
// surfaces there (the door's 6 cm strip was 90 % of lumen's error at 256 x 256; docs/gi.md, energy
// 45.). Writes each tile's candidate pixel and each tile row's count of them; the allocation pass
// then gives the candidates slots in tile order. One group per row of tiles, its threads taking
// every LUMINA_SP_ADAPTIVE_ROW_GROUP-th tile of the row.
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<ScreenProbe> gProbes : register(t2);    // this frame's uniform grid
RWStructuredBuffer<uint> gCandidates : register(u0);     // per tile: packAdaptivePixel or none
RWStructuredBuffer<uint> gRowWanted : register(u1);      // per tile row: its tiles that want a probe

groupshared uint gsWanted[LUMINA_SP_ADAPTIVE_ROW_GROUP];

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

// The tile's least covered surface pixel if it is covered below the threshold, else none.
uint tileCandidate(uint2 tile) {
    const uint spacing = gSp.adaptiveSpacing;
    float worst = LUMINA_SP_ADAPTIVE_COVERAGE;
    uint candidate = LUMINA_SP_NO_ADAPTIVE_PROBE;
    for (uint i = 0u; i < spacing * spacing; ++i) {
        const uint2 pixel = tile * spacing + uint2(i % spacing, i / spacing);
        const bool inside = all(pixel < gSp.imageSize);
        const float4 normal = inside ? gNormal.Load(int3(pixel, 0)) : float4(0.0, 0.0, 0.0, 0.0);
        const float4 position = inside ? gPosition.Load(int3(pixel, 0)) : float4(0.0, 0.0, 0.0, 0.0);
        const float normalLength = length(normal.xyz);
        const bool surface = normal.w > 0.0 && position.w > 0.0 && normalLength > 0.0 &&
                             allFinite3(position.xyz) && allFinite3(normal.xyz);
        if (surface) {
            const float coverage = uniformCoverage(pixel, position, normal.xyz / normalLength);
            if (coverage < worst) {
                worst = coverage;
                candidate = packAdaptivePixel(pixel);
            }
        }
    }
    return candidate;
}

[numthreads(LUMINA_SP_ADAPTIVE_ROW_GROUP, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint2 tiles = adaptiveGrid();
    const uint row = group.x;
    if (row >= tiles.y) {
        return;
    }
    uint wanted = 0u;
    for (uint x = t; x < tiles.x; x += LUMINA_SP_ADAPTIVE_ROW_GROUP) {
        const uint candidate = tileCandidate(uint2(x, row));
        gCandidates[row * tiles.x + x] = candidate;
        wanted += candidate != LUMINA_SP_NO_ADAPTIVE_PROBE ? 1u : 0u;
    }
    gsWanted[t] = wanted;
    GroupMemoryBarrierWithGroupSync();
    if (t == 0u) {
        uint sum = 0u;
        for (uint i = 0u; i < LUMINA_SP_ADAPTIVE_ROW_GROUP; ++i) {
            sum += gsWanted[i];
        }
        gRowWanted[row] = sum;
    }
}
