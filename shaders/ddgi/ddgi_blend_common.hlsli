#ifndef LUMINA_DDGI_BLEND_COMMON_HLSLI
#define LUMINA_DDGI_BLEND_COMMON_HLSLI
// What the irradiance and distance blends share: one group per probe, one thread per interior
// texel of its tile. The group first loads the probe's blended rays (every ray but the fixed
// set) into groupshared memory, each thread then folds them into its texel's direction, and
// finally the border texels are copied from the interior values the group kept, so the whole
// tile is written by one dispatch. Include after declaring gProbes and gRayData.
#include "ddgi/ddgi_common.hlsli"
#include "screen_probes/octahedral_shared.h"

groupshared float4 gsRayDirection[LUMINA_DDGI_MAX_RAYS]; // xyz: direction
groupshared float4 gsRayData[LUMINA_DDGI_MAX_RAYS];      // rgb: radiance; a: signed distance
groupshared uint gsProbeState;

// Loads probe `probe`'s blended rays; false (for the whole group) when the probe is inactive or
// out of range. `threads`: the group's size.
bool loadProbeRays(uint probe, uint thread, uint threads) {
    if (thread == 0u) {
        gsProbeState = probe < gDdgi.probeCount ? uint(gProbes[probe].offsetAndState.w) : 2u;
    }
    GroupMemoryBarrierWithGroupSync();
    if (gsProbeState == uint(LUMINA_DDGI_PROBE_INACTIVE)) {
        return false;
    }
    const uint fixedRays = gDdgi.fixedRays;
    for (uint r = fixedRays + thread; r < gDdgi.raysPerProbe; r += threads) {
        gsRayDirection[r - fixedRays] = float4(ddgiRayDirection(r), 0.0);
        gsRayData[r - fixedRays] = gRayData[probe * gDdgi.raysPerProbe + r];
    }
    GroupMemoryBarrierWithGroupSync();
    return true;
}

// The texel a blend thread folds the rays into.
struct BlendTexel {
    DdgiProbeRef ref;  // its probe
    uint2 local;       // interior texel (x, y) of the n x n map
    float3 direction;  // the map's direction at its centre
};

// Loads probe `probe`'s rays for a group of n x n threads (thread t: texel t % n, t / n); false
// for the whole group when the probe is inactive.
bool beginBlend(uint probe, uint t, uint n, out BlendTexel texel) {
    texel.ref = ddgiProbeRef(min(probe, gDdgi.probeCount - 1u));
    texel.local = uint2(t % n, t / n);
    texel.direction = octDecode(octTexelCentre(texel.local.x, texel.local.y, n));
    return loadProbeRays(probe, t, n * n);
}

uint blendedRayCount() {
    return gDdgi.raysPerProbe - gDdgi.fixedRays;
}

// The share of history kept: none for a fresh probe, else the hysteresis.
float blendHysteresis() {
    return gsProbeState == uint(LUMINA_DDGI_PROBE_FRESH) ? 0.0 : gDdgi.hysteresis;
}

// Border texel b of an n x n tile with its border (false past the last, 4n + 3): its position in
// the bordered tile and the row-major index of the interior texel it repeats
// (octBorderedTexelPosition: mirrored across the seams). After a group sync, thread b writes it.
bool borderTexel(uint b, uint n, out uint2 bordered, out uint interior) {
    const uint side = n + 2u;
    if (b < side) {
        bordered = uint2(b, 0u); // top row
    } else if (b < 2u * side) {
        bordered = uint2(b - side, side - 1u); // bottom row
    } else if (b < 2u * side + n) {
        bordered = uint2(0u, b - 2u * side + 1u); // left column
    } else {
        bordered = uint2(side - 1u, b - 2u * side - n + 1u); // right column
    }
    interior = octTexelOf(octBorderedTexelPosition(bordered.x, bordered.y, n), n);
    return b < 4u * n + 4u;
}

#endif
