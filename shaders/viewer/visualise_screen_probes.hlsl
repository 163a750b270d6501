// lumina-kernel: cs rayDirections
// lumina-kernel: cs shRadiance
// The viewer's views of the screen probes' rays and SH (app/viewer/gi_views.cpp), tiled per
// probe like the other probe views (visualise_common.hlsli, probeEntry):
//   rayDirections: each ray of the probe's list, in the order the ray generation wrote them: its
//                  world direction as d / 2 + 1/2 (the colours of a normal view), black where
//                  the ray was not traced.
//   shRadiance:    the SH low-pass's radiance (9 coefficients per channel, world space)
//                  evaluated at the centre direction of each texel of the probe's
//                  hemi-octahedral map, beside which the filtered radiance view shows what it
//                  was projected from; black for probes on the sky.
#include "viewer/visualise_common.hlsli"
#include "screen_probes/screen_probe_shared.h"

StructuredBuffer<ProbeRay> gRays : register(t0);
StructuredBuffer<float4> gSh : register(t1); // LUMINA_SH_COEFFICIENTS per probe: rgb per coefficient
StructuredBuffer<ScreenProbe> gProbes : register(t2);

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void rayDirections(uint3 id : SV_DispatchThreadID) {
    uint probe, entry;
    if (probeEntry(id.xy, probe, entry)) {
        const ProbeRay ray = gRays[probe * gVisualise.entriesPerProbe + entry];
        const float3 color = ray.info.z != 0u ? saturate(ray.directionAndWeight.xyz * 0.5 + 0.5) : float3(0.0, 0.0, 0.0);
        gOutput[id.xy] = float4(color, 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void shRadiance(uint3 id : SV_DispatchThreadID) {
    uint probe, entry;
    if (!probeEntry(id.xy, probe, entry)) {
        return;
    }
    const ScreenProbe p = gProbes[probe];
    float3 radiance = float3(0.0, 0.0, 0.0);
    if ((p.info.x & LUMINA_SP_PROBE_VALID) != 0u) {
        const float2 e = octTexelCentre(entry % LUMINA_SP_OCT_SIZE, entry / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
        const float3 d = probeToWorld(probeFrame(p.normal.xyz), hemiOctDecode(e));
        for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
            radiance += gSh[probe * LUMINA_SH_COEFFICIENTS + k].rgb * shBasis(k, d);
        }
    }
    gOutput[id.xy] = float4(display(float4(max(radiance, 0.0), 1.0)), 1.0);
}
