// lumina-kernel: cs main
// Pass 1c, adaptive allocation: the adaptive placement's candidates get the adaptive slots in tile
// order (row by row, left to right), so which tile holds which slot, and which tiles go without
// when there are more candidates than slots, is the same on every run and every GPU. A group's row
// starts after the candidates of every row above it (the placement's counts per run of
// LUMINA_SP_ADAPTIVE_RUN tiles); within the row a prefix sum over each run numbers them. When the
// whole image wants more probes than there are slots, the slots are shared evenly over the
// candidates in tile order (spAdaptiveShare), so every part of the image keeps its share rather
// than the top rows taking them all. A candidate with a slot gets a probe there, at its pixel's
// GBuffer surface; every tile's slot (or none) goes to the adaptive index. The last row writes the
// total wanted, which `lumina render` reports. One group per row of tiles.
#include "screen_probes/adaptive_share_shared.h"
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<uint> gCandidates : register(t2);      // per tile: packAdaptivePixel or none
StructuredBuffer<uint> gRunWanted : register(t3);       // per run of tiles: its candidates
RWStructuredBuffer<ScreenProbe> gProbes : register(u0); // the adaptive slots (placement emptied them)
RWStructuredBuffer<uint> gAdaptiveIndex : register(u1); // per tile: its probe's slot or none
RWStructuredBuffer<uint> gAdaptiveWanted : register(u2); // [0]: candidates in the whole image

groupshared uint gsScan[LUMINA_SP_ADAPTIVE_RUN];

// Inclusive prefix sum of `value` over the group's threads (Hillis-Steele); the group's total is
// then in gsScan[last].
uint inclusiveScan(uint t, uint value) {
    GroupMemoryBarrierWithGroupSync(); // every read of the last scan is done
    gsScan[t] = value;
    GroupMemoryBarrierWithGroupSync();
    for (uint offset = 1u; offset < LUMINA_SP_ADAPTIVE_RUN; offset <<= 1u) {
        const uint add = t >= offset ? gsScan[t - offset] : 0u;
        GroupMemoryBarrierWithGroupSync();
        gsScan[t] += add;
        GroupMemoryBarrierWithGroupSync();
    }
    return gsScan[t];
}

[numthreads(LUMINA_SP_ADAPTIVE_RUN, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint2 tiles = adaptiveGrid();
    const uint row = group.x;
    if (row >= tiles.y) {
        return;
    }
    const uint runs = tiles.y * adaptiveRunsPerRow(tiles);
    const uint runsAbove = row * adaptiveRunsPerRow(tiles);
    uint above = 0u;
    uint all = 0u;
    for (uint i = t; i < runs; i += LUMINA_SP_ADAPTIVE_RUN) {
        const uint runWanted = gRunWanted[i];
        all += runWanted;
        above += i < runsAbove ? runWanted : 0u;
    }
    inclusiveScan(t, all);
    const uint wanted = gsScan[LUMINA_SP_ADAPTIVE_RUN - 1u];
    inclusiveScan(t, above);
    uint next = gsScan[LUMINA_SP_ADAPTIVE_RUN - 1u]; // candidates before this run of tiles
    const uint slots = gSp.probeCount - gSp.uniformProbeCount;
    for (uint start = 0u; start < tiles.x; start += LUMINA_SP_ADAPTIVE_RUN) {
        const uint x = start + t;
        const uint tile = row * tiles.x + x;
        const uint candidate = x < tiles.x ? gCandidates[tile] : LUMINA_SP_NO_ADAPTIVE_PROBE;
        const bool wants = candidate != LUMINA_SP_NO_ADAPTIVE_PROBE;
        // The probe is made before the scan: built after it, Wine's D3D12 stored the slot as the
        // pixel's x (docs/d3d12.md, "Compiler differences").
        const uint2 pixel = wants ? unpackAdaptivePixel(candidate) : uint2(0u, 0u);
        ScreenProbe probe;
        probe.info = uint4(LUMINA_SP_PROBE_VALID, pixel, 0u);
        probe.positionAndDepth = gPosition.Load(int3(pixel, 0));
        probe.normal = float4(normalize(gNormal.Load(int3(pixel, 0)).xyz), 0.0);
        const uint rank = next + inclusiveScan(t, wants ? 1u : 0u) - 1u;
        next += gsScan[LUMINA_SP_ADAPTIVE_RUN - 1u];
        uint2 share = uint2(0u, 0u);
        if (wants) {
            share = spAdaptiveShare(rank, slots, wanted);
        }
        uint slot = LUMINA_SP_NO_ADAPTIVE_PROBE;
        if (share.y != 0u) {
            slot = gSp.uniformProbeCount + share.x;
            gProbes[slot] = probe;
        }
        if (x < tiles.x) {
            gAdaptiveIndex[tile] = slot;
        }
    }
    if (row == tiles.y - 1u && t == 0u) {
        gAdaptiveWanted[0] = wanted;
    }
}
