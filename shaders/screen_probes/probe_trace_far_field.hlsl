// lumina-kernel: cs main
// Pass 6, far-field trace: every ray of every valid probe cone-traced through the global SDF
// (sdfConeTraceGlobal), from the probe position lifted off its surface along the normal (the
// global SDF is coarse: starting on the surface would hit it at once). Writes one hit record per
// ray (SdfHit: distance, position, normal, miss flag); probe_ray_shading turns them into radiance.
// One group per probe; thread t traces rays t, t + 64, ...
#include "sdf/sdf_scene_bindings.hlsli"
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t6);
StructuredBuffer<ProbeRay> gRays : register(t7);
RWStructuredBuffer<SdfHit> gHits : register(u0);

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.grid.w || !probeIsValid(gProbes[probe])) {
        return;
    }
    const ScreenProbe p = gProbes[probe];
    const float3 origin = p.positionAndDepth.xyz + p.normal.xyz * gSp.trace.z;
    const SdfTraceParams params = sdfDefaultTraceParams(gSp.trace.x);
    const uint rayCount = gSp.rays.x;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const float3 direction = gRays[probe * rayCount + r].directionAndWeight.xyz;
        gHits[probe * rayCount + r] = sdfConeTraceGlobal(origin, direction, 0.0, gSp.trace.y, params);
    }
}
