// lumina-kernel: cs main
// DDGI reset: every probe of a volume flagged LUMINA_DDGI_VOLUME_RESET (its first update, a
// cascade that moved with the camera, a reset of history) returns to its lattice point as a
// fresh probe: the next blend takes its rays whole, whatever its tiles held. One thread per probe.
#include "ddgi/ddgi_common.hlsli"

RWStructuredBuffer<DdgiProbe> gProbes : register(u0);

[numthreads(LUMINA_DDGI_PROBE_GROUP, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x < gDdgi.rays.w &&
        (gDdgi.volumes[ddgiProbeRef(id.x).volume].atlas.z & LUMINA_DDGI_VOLUME_RESET) != 0u) {
        DdgiProbe p;
        p.offsetAndState = float4(0.0, 0.0, 0.0, LUMINA_DDGI_PROBE_FRESH);
        gProbes[id.x] = p;
    }
}
