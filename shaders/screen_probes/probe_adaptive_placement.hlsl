// lumina-kernel: cs main
// Pass 1b, adaptive placement: where adaptive probes are wanted. The image is cut into adaptive
// tiles of adaptiveSpacing (half the probe spacing) pixels a side; in each, the surface pixel whose
// best corner probe weighs least (probeSurfaceWeight, the gather's weight) is found, and if that
// weight is below LUMINA_SP_ADAPTIVE_COVERAGE the tile wants a probe at that pixel. Such pixels lie
// on a surface no cell centre saw: a strip of wall between a doorway's jamb and an open door, a thin
// object, a silhouette whose cell centres see the sky. Without them the gather reads probes on other
// surfaces there (the door's 6 cm strip was 90 % of lumen's error at 256 x 256; docs/gi.md, energy
// 45.). Writes each tile's candidate pixel and each run of LUMINA_SP_ADAPTIVE_RUN tiles' count of
// them; the allocation pass then gives the candidates slots in tile order. A thread per tile, a
// group per run: one group per row took 2.6 times as long on the H200, a few hundred groups
// being too few to fill it.
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<ScreenProbe> gProbes : register(t2);    // this frame's uniform grid
RWStructuredBuffer<uint> gCandidates : register(u0);     // per tile: packAdaptivePixel or none
RWStructuredBuffer<uint> gRunWanted : register(u1);      // per run of tiles: those that want a probe

groupshared uint gsWanted[LUMINA_SP_ADAPTIVE_RUN];

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

[numthreads(LUMINA_SP_ADAPTIVE_RUN, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint2 tiles = adaptiveGrid();
    const uint run = group.x, row = group.y;
    const uint x = run * LUMINA_SP_ADAPTIVE_RUN + t;
    uint candidate = LUMINA_SP_NO_ADAPTIVE_PROBE;
    if (x < tiles.x && row < tiles.y) {
        candidate = tileCandidate(uint2(x, row));
        gCandidates[row * tiles.x + x] = candidate;
    }
    gsWanted[t] = candidate != LUMINA_SP_NO_ADAPTIVE_PROBE ? 1u : 0u;
    GroupMemoryBarrierWithGroupSync();
    if (t == 0u && row < tiles.y) {
        uint sum = 0u;
        for (uint i = 0u; i < LUMINA_SP_ADAPTIVE_RUN; ++i) {
            sum += gsWanted[i];
        }
        gRunWanted[row * adaptiveRunsPerRow(tiles) + run] = sum;
    }
}
