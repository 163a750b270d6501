// lumina-kernel: cs main
// DDGI classification: a probe is switched off when no shaded point can use it, because no
// surface lies within its cells (no fixed ray hits anything within one cell along every axis: no
// surface it would light is in the eight cells around it), or because it still sits inside
// geometry after relocation (more back-face hits than the backface fraction: what it sees is the
// inside of a solid). Inactive probes trace only their fixed rays, are not blended and weigh
// nothing in ddgi_sample: each is a probe's worth of rays and blend skipped. A probe switched on
// again starts fresh (its tiles are stale); a fresh probe blended this update becomes active.
// One thread per probe; with classification off every probe stays active.
#include "ddgi/ddgi_fixed_rays.hlsli"

[numthreads(LUMINA_DDGI_PROBE_GROUP, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint probe = id.x;
    DdgiProbe p;
    if (!threadProbe(id, p)) {
        return;
    }
    const float state = p.offsetAndState.w;
    bool inactive = false;
    if (gDdgi.classification != 0u) {
        const DdgiProbeRef ref = ddgiProbeRef(probe);
        const DdgiFixedRayStats s = fixedRayStats(probe, gDdgi.volumes[ref.volume].spacing);
        inactive = probeInsideGeometry(s) || !s.surfaceInCells;
    }
    if (inactive) {
        p.offsetAndState.w = LUMINA_DDGI_PROBE_INACTIVE;
    } else {
        // Blended this update (fresh or active): history from now on; woken up: stale tiles.
        p.offsetAndState.w =
            state == LUMINA_DDGI_PROBE_INACTIVE ? LUMINA_DDGI_PROBE_FRESH : LUMINA_DDGI_PROBE_ACTIVE;
    }
    gProbes[probe] = p;
}
