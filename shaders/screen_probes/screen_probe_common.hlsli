#ifndef LUMINA_SCREEN_PROBE_COMMON_HLSLI
#define LUMINA_SCREEN_PROBE_COMMON_HLSLI
// What the screen-probe kernels share: their constants (b1), the probe a per-probe group works
// on, finding a probe's history in the previous frame, and sanitising values headed for history.
#include "common/bindings.hlsli"
#include "common/conventions.h"
#include "screen_probes/probe_sampling_shared.h"
#include "screen_probes/screen_probe_shared.h"

ConstantBuffer<ScreenProbeConstants> gSp : register(b1);

// Per-probe passes dispatch one group per probe over the probe grid.
uint probeIndexOfGroup(uint3 group) {
    return group.y * gSp.probeGrid.x + group.x;
}

bool probeIsValid(ScreenProbe probe) {
    return (probe.info.x & LUMINA_SP_PROBE_VALID) != 0u;
}

// Slots from uniformProbeCount on hold adaptive probes (probe_adaptive_placement.hlsl).
bool isAdaptiveProbe(uint probe) {
    return probe >= gSp.uniformProbeCount;
}

// Adaptive tiles across and down (none when adaptive probes are off).
uint2 adaptiveGrid() {
    const uint s = max(gSp.adaptiveSpacing, 1u);
    return gSp.adaptiveSpacing > 0u ? (gSp.imageSize + s - 1u) / s : uint2(0u, 0u);
}

// Runs of LUMINA_SP_ADAPTIVE_RUN tiles in a row of `tiles` (adaptiveGrid()).
uint adaptiveRunsPerRow(uint2 tiles) {
    return (tiles.x + LUMINA_SP_ADAPTIVE_RUN - 1u) / LUMINA_SP_ADAPTIVE_RUN;
}

// A candidate pixel of the adaptive placement in one uint (images are narrower than 65,536).
uint packAdaptivePixel(uint2 pixel) {
    return pixel.x | (pixel.y << 16u);
}

uint2 unpackAdaptivePixel(uint packed) {
    return uint2(packed & 0xffffu, packed >> 16u);
}

// How surely a pixel at `position` (w: view depth) with unit normal n lies on probe p's surface:
// exp(-plane distance / (filterPlaneScale x view depth)) x max(0, n . n_p)^filterNormalPower. The gather
// weighs probes by it; adaptive placement puts a probe where the uniform grid offers no good one.
float probeSurfaceWeight(ScreenProbe p, float4 position, float3 n) {
    const float planeDistance = abs(dot(position.xyz - p.positionAndDepth.xyz, p.normal.xyz));
    return exp(-planeDistance / (gSp.filterPlaneScale * position.w)) *
           pow(saturate(dot(n, p.normal.xyz)), gSp.filterNormalPower);
}

// Corner k (0..3) of the uniform probe cell around pixel centre `pixel`: the probe's index and its
// bilinear weight.
uint uniformCorner(uint2 pixel, uint k, out float bilinear) {
    const float2 g = (float2(pixel) + 0.5) / float(gSp.probeSpacing) - 0.5;
    const int2 base = int2(floor(g));
    const float2 f = g - float2(base);
    const int2 corner = int2(k & 1u, k >> 1u);
    const int2 cell = clamp(base + corner, int2(0, 0), int2(gSp.probeGrid) - 1);
    const float2 bw = lerp(1.0 - f, f, float2(corner));
    bilinear = bw.x * bw.y;
    return uint(cell.y) * gSp.probeGrid.x + uint(cell.x);
}

bool hasFlag(uint flag) {
    return (gSp.flags & flag) != 0u;
}

bool allFinite3(float3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// World position to a pixel position of the previous frame's camera; false behind it or off screen.
bool previousPixel(float3 world, out float2 pixel) {
    const float4 p = float4(world, 1.0);
    const float4 clip =
        float4(dot(gSp.previousCamera.viewProjRows[0], p), dot(gSp.previousCamera.viewProjRows[1], p),
               dot(gSp.previousCamera.viewProjRows[2], p), dot(gSp.previousCamera.viewProjRows[3], p));
    if (clip.w <= 0.0) {
        pixel = float2(0.0, 0.0);
        return false;
    }
    const float2 ndc = clip.xy / clip.w;
    pixel = float2(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y) * float2(gSp.imageSize);
    return all(pixel >= 0.0) && all(pixel < float2(gSp.imageSize));
}

// The previous frame's probe at the cell this probe's position projects to there, or -1. Probes sit
// at cell centres, so the candidate lies within about a cell of where the surface was seen.
int historyProbeCandidate(float3 world) {
    float2 pixel;
    if (!hasFlag(LUMINA_SP_FLAG_PROBE_HISTORY) || !previousPixel(world, pixel)) {
        return -1;
    }
    const uint2 cell = min(uint2(pixel) / gSp.probeSpacing, gSp.probeGrid - 1u);
    return int(cell.y * gSp.probeGrid.x + cell.x);
}

// Whether the old probe saw the same surface: valid, on the new probe's plane (within
// historyPlaneTolerance x view depth), facing the same way (cosine at least historyNormalTolerance) and within
// LUMINA_SP_HISTORY_MAX_CELLS cells' world size of it. A probe that moved in world space
// (disocclusion, a moved object) loses its history.
// The share of its weight that history at `world` keeps: the least of the change regions holding
// it, 1 outside them (gi/screen_probes/screen_probe_gather.h, invalidateHistory).
float historyKeep(float3 world) {
    float keep = 1.0;
    for (uint i = 0u; i < gSp.changeRegionCount; ++i) {
        const ChangeRegion region = gSp.changeRegions[i];
        if (all(world >= region.boxMin) && all(world <= region.boxMax)) {
            keep = min(keep, region.historyKept);
        }
    }
    return keep;
}

bool historyMatches(ScreenProbe current, ScreenProbe previous) {
    if (!probeIsValid(previous)) {
        return false;
    }
    const float depth = current.positionAndDepth.w;
    const float3 offset = previous.positionAndDepth.xyz - current.positionAndDepth.xyz;
    const float cellWorld = float(gSp.probeSpacing) * 2.0 * gSp.camera.tanHalfFovY * depth *
                            gSp.camera.invImageSize.y;
    return abs(dot(offset, current.normal.xyz)) <= gSp.historyPlaneTolerance * depth &&
           dot(previous.normal.xyz, current.normal.xyz) >= gSp.historyNormalTolerance &&
           length(offset) <= LUMINA_SP_HISTORY_MAX_CELLS * cellWorld;
}

// Texel of a probe's map (frame f) that holds world direction d, or -1 below its hemisphere.
int texelInFrame(ProbeFrame f, float3 d) {
    // One return (the DXBC path miscompiles early returns taken inside loops; docs/d3d12.md).
    const float3 local = worldToProbe(f, d);
    return local.z > 0.0 ? int(octTexelOf(hemiOctEncode(local), LUMINA_SP_OCT_SIZE)) : -1;
}

// Solid angle of texel t of a probe's map (the same for every probe: the map is in its frame).
float texelSolidAngle(uint t) {
    return hemiOctTexelSolidAngle(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
}

// Texel t's share of the cosine-weighted hemisphere, (1 / pi) times the integral of cos over it.
float texelCosineMass(uint t) {
    return hemiOctTexelCosineMass(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
}

// World direction of the centre of texel t of a probe's map.
float3 texelDirection(ProbeFrame f, uint t) {
    const float2 e = octTexelCentre(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
    return probeToWorld(f, hemiOctDecode(e));
}

#endif
