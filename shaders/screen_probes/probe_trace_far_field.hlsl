// lumina-kernel: cs main
// Pass 6, far-field trace: every ray of every valid probe cone-traced through the global SDF
// (sdfConeTraceGlobal), from the probe position lifted off its surface along the normal (the
// global SDF is coarse: starting on the surface would hit it at once). Writes one hit record per
// ray (SdfHit: distance, position, normal, miss flag); probe_ray_shading turns them into radiance.
// After the near field (LUMINA_SP_FLAG_NEAR_FIELD), only the rays it missed are traced, from the
// near-field distance on: a near hit keeps the hit record the near field wrote.
// One group per probe; thread t traces rays t, t + 64, ...
#include "screen_probes/probe_trace_common.hlsli"

StructuredBuffer<float4> gNearField : register(t8); // a: LUMINA_SP_NEAR_*, with LUMINA_SP_FLAG_NEAR_FIELD
RWStructuredBuffer<SdfHit> gHits : register(u0);

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    uint probe;
    float3 origin;
    if (!tracedProbe(group, t, probe, origin)) {
        return;
    }
    const SdfTraceParams params = sdfDefaultTraceParams(gSp.maxTraceDistance);
    const bool nearField = hasFlag(LUMINA_SP_FLAG_NEAR_FIELD);
    const float tMin = nearField ? gSp.nearFieldDistance : 0.0;
    const uint rayCount = gSp.raysPerProbe;
    for (uint r = t; r < rayCount; r += LUMINA_SP_PROBE_TEXELS) {
        const uint ray = probe * rayCount + r;
        if (nearField && gNearField[ray].a != float(LUMINA_SP_NEAR_MISS)) {
            continue;
        }
        const float3 direction = gRays[ray].directionAndWeight.xyz;
        gHits[ray] = sdfConeTraceGlobal(probeRayStart(gProbes[probe], origin, direction), direction, tMin,
                                        gSp.coneTanHalfAngle, params);
    }
}
