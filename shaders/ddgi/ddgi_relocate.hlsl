// lumina-kernel: cs main
// DDGI relocation: a probe inside geometry, or nearer a front face than the allowed fraction of
// its cell, moves within its cell, so that its rays start in open space and its visibility
// describes the room it serves. Judged from the fixed rays (the same directions every update):
// - inside (more back-face hits than the backface fraction): out along the global SDF's
//   gradient by the depth there plus the allowed distance (a ray from inside a closed mesh stops
//   at once, so the rays give no direction; the SDF does);
// - too near a front face: away from the nearest hit by what is missing.
// The offset stays within the max offset fraction of a cell per axis, so a probe never leaves the
// trilinear cell it weights. Repeats every update: the offset settles over a few. One thread
// per probe; with relocation off every offset is zero.
#include "ddgi/ddgi_common.hlsli"
#include "sdf/sdf_scene_bindings.hlsli"

#include "ddgi/ddgi_fixed_rays.hlsli"

[numthreads(LUMINA_DDGI_PROBE_GROUP, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint probe = id.x;
    DdgiProbe p;
    if (!threadProbe(id, p)) {
        return;
    }
    if (gDdgi.relocation == 0u) {
        p.offsetAndState.xyz = float3(0.0, 0.0, 0.0);
        gProbes[probe] = p;
        return;
    }
    const DdgiProbeRef ref = ddgiProbeRef(probe);
    const DdgiVolumeInfo volume = gDdgi.volumes[ref.volume];
    const float3 spacing = volume.spacing;
    const float allowed = gDdgi.minFrontfaceDistance * min(spacing.x, min(spacing.y, spacing.z));
    const DdgiFixedRayStats s = fixedRayStats(probe, spacing);
    float3 offset = p.offsetAndState.xyz;
    if (probeInsideGeometry(s)) {
        const float3 position = ddgiProbePosition(ref, p);
        const float depth = max(0.0, -sdfSampleGlobal(position));
        offset += sdfGlobalNormal(position) * (depth + allowed);
    } else if (s.closestFront < allowed) {
        offset -= s.closestFrontDirection * (allowed - s.closestFront);
    }
    const float3 limit = volume.maxOffset * spacing;
    p.offsetAndState.xyz = clamp(offset, -limit, limit);
    gProbes[probe] = p;
}
