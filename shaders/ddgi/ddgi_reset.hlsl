// lumina-kernel: cs main
// DDGI reset: a probe returns to its lattice point as a fresh probe (the next blend takes its rays
// whole, whatever its tiles held) when its volume is flagged LUMINA_DDGI_VOLUME_RESET (its first
// update, a cascade that jumped farther than its own size) or when its lattice point entered the
// volume with this update's scroll (the planes a camera-centred cascade gained on the side it
// moved to; the slots they reuse held the planes it left). One thread per probe.
#include "ddgi/ddgi_common.hlsli"

RWStructuredBuffer<DdgiProbe> gProbes : register(u0);

bool entered(DdgiVolumeInfo v, uint3 lattice) {
    return any(lattice >= v.enteredMin && lattice < v.enteredMax);
}

[numthreads(LUMINA_DDGI_PROBE_GROUP, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gDdgi.probeCount) {
        return;
    }
    const DdgiProbeRef ref = ddgiProbeRef(id.x);
    const DdgiVolumeInfo v = gDdgi.volumes[ref.volume];
    const uint3 lattice = ddgiLatticeOfSlot(v, ddgiProbeCoord(ref.local, v.counts));
    if ((v.flags & LUMINA_DDGI_VOLUME_RESET) != 0u || entered(v, lattice)) {
        DdgiProbe p;
        p.offsetAndState = float4(0.0, 0.0, 0.0, LUMINA_DDGI_PROBE_FRESH);
        gProbes[id.x] = p;
    }
}
