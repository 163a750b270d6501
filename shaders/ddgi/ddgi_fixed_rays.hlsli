#ifndef LUMINA_DDGI_FIXED_RAYS_HLSLI
#define LUMINA_DDGI_FIXED_RAYS_HLSLI
// What relocation and classification read of a probe's fixed rays (the first gDdgi.fixedRays, in
// the same directions every update): how many hit a back face, the nearest front face, and
// whether any surface lies within the probe's cells; and the bindings the two passes share: this
// update's rays (t6; relocation binds the SDF scene below it) and the probes they rewrite (u0).
#include "ddgi/ddgi_common.hlsli"

StructuredBuffer<float4> gRayData : register(t6);
RWStructuredBuffer<DdgiProbe> gProbes : register(u0);

// The probe of a one-thread-per-probe dispatch; false past the last probe.
bool threadProbe(uint3 id, out DdgiProbe p) {
    p.offsetAndState = float4(0.0, 0.0, 0.0, 0.0);
    if (id.x >= gDdgi.probeCount) {
        return false;
    }
    p = gProbes[id.x];
    return true;
}

struct DdgiFixedRayStats {
    uint backfaces;
    float closestFront; // distance of the nearest front-face hit (max trace distance: none)
    float3 closestFrontDirection;
    bool surfaceInCells; // a hit (either face) within one cell of the probe along every axis
};

DdgiFixedRayStats fixedRayStats(uint probe, float3 spacing) {
    DdgiFixedRayStats s;
    s.backfaces = 0u;
    s.closestFront = gDdgi.maxTraceDistance;
    s.closestFrontDirection = float3(0.0, 0.0, 1.0);
    s.surfaceInCells = false;
    for (uint r = 0u; r < gDdgi.fixedRays; ++r) {
        const float signedDistance = gRayData[probe * gDdgi.raysPerProbe + r].a;
        const float3 direction = ddgiRayDirection(r);
        const float distance = abs(signedDistance);
        if (signedDistance < 0.0) {
            s.backfaces += 1u;
        } else if (distance < s.closestFront) {
            s.closestFront = distance;
            s.closestFrontDirection = direction;
        }
        if (distance < gDdgi.maxTraceDistance && all(abs(direction * distance) <= spacing)) {
            s.surfaceInCells = true;
        }
    }
    return s;
}

// More than the backface fraction of the fixed rays left from inside a surface.
bool probeInsideGeometry(DdgiFixedRayStats s) {
    return float(s.backfaces) > gDdgi.backfaceFraction * float(gDdgi.fixedRays);
}

#endif
