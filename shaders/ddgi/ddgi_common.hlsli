#ifndef LUMINA_DDGI_COMMON_HLSLI
#define LUMINA_DDGI_COMMON_HLSLI
// What every DDGI kernel shares (docs/ddgi.md): the constants (b1; b0 is the SDF scene's in the
// trace), which volume a global probe index belongs to, where a probe is, and where its rays go.
#include "common/bindings.hlsli"
#include "ddgi/ddgi_shared.h"

ConstantBuffer<DdgiConstants> gDdgi : register(b1);

struct DdgiProbeRef {
    uint volume; // index into gDdgi.volumes
    uint local;  // probe index inside the volume
};

// The volume holding global probe `probe` (< gDdgi.probeCount).
DdgiProbeRef ddgiProbeRef(uint probe) {
    DdgiProbeRef ref;
    ref.volume = 0u;
    for (uint v = 1u; v < gDdgi.volumeCount; ++v) {
        if (probe >= gDdgi.volumes[v].firstProbe) {
            ref.volume = v;
        }
    }
    ref.local = probe - gDdgi.volumes[ref.volume].firstProbe;
    return ref;
}

// World position of a probe: its lattice point moved by its relocation offset.
float3 ddgiProbePosition(DdgiProbeRef ref, DdgiProbe probe) {
    const DdgiVolumeInfo v = gDdgi.volumes[ref.volume];
    return ddgiLatticePosition(v, ddgiLatticeOfSlot(v, ddgiProbeCoord(ref.local, v.counts))) +
           probe.offsetAndState.xyz;
}

// Ray `ray` of every probe this update: the fixed set unrotated, the rest a spherical Fibonacci
// set under this update's random rotation (a fresh one each update, so that the blended history
// sees ever new directions).
float3 ddgiRayDirection(uint ray) {
    const uint fixedRays = gDdgi.fixedRays;
    if (ray < fixedRays) {
        return ddgiFibonacciDirection(ray, fixedRays);
    }
    const float3 d = ddgiFibonacciDirection(ray - fixedRays, gDdgi.raysPerProbe - fixedRays);
    return float3(dot(gDdgi.rotation[0].xyz, d), dot(gDdgi.rotation[1].xyz, d),
                  dot(gDdgi.rotation[2].xyz, d));
}

bool ddgiProbeInactive(DdgiProbe probe) {
    return probe.offsetAndState.w == LUMINA_DDGI_PROBE_INACTIVE;
}

// NaN and Inf never enter history: anything not a finite non-negative value becomes 0
// (written without isnan, which the DXBC compiler lacks).
float3 ddgiSanitise(float3 v) {
    const float kLargest = 3.0e38;
    return float3(v.x >= 0.0 && v.x <= kLargest ? v.x : 0.0, v.y >= 0.0 && v.y <= kLargest ? v.y : 0.0,
                  v.z >= 0.0 && v.z <= kLargest ? v.z : 0.0);
}

#endif
