#ifndef LUMINA_PROBE_TRACE_COMMON_HLSLI
#define LUMINA_PROBE_TRACE_COMMON_HLSLI
// What the near-field and far-field traces share, bound by probeTracePass
// (gi/screen_probes/probe_trace_bindings.h): the SDF scene (b0, t0-t5, s0), the constants (b1),
// this frame's probes (t6) and the rays (t7); and where a probe's rays start.
#include "sdf/sdf_scene_bindings.hlsli"
#include "sdf/surface_line_start.hlsli"
#include "screen_probes/screen_probe_common.hlsli"

#define LUMINA_SP_ORIGIN_PUSH_STEPS 4u

StructuredBuffer<ScreenProbe> gProbes : register(t6);
StructuredBuffer<ProbeRay> gRays : register(t7);

// Where a probe's rays start: its position lifted off the surface along its normal by the origin
// bias (the global SDF is coarse: starting on the surface would hit it at once), then out of any
// other surface's shell.
float3 probeRayOrigin(ScreenProbe p) {
    float3 origin = p.positionAndDepth.xyz + p.normal.xyz * gSp.originBias;
    // A probe in a corner (a wall meeting the floor) lifted along its own normal can stay within
    // the other surface's SDF shell, where every ray hits at t = 0 and reads whichever card the
    // gradient there names: in the open-top box, the sunlit outside of the wall, a bright "+" in
    // the image where the spatial filter spread that probe. So the origin is pushed out along the
    // global SDF's gradient until it lies half the lift clear of every surface. Where three
    // zero-thickness quads meet within a global voxel (the open-top box's room corners) that
    // gradient can point out of the room, and the push leaves the room (docs/gi.md, defects). Nor
    // does the gradient within a hundredth of a voxel of one zero-thickness wall, whose unsigned
    // field has no side: in sunlit_rooms a floor probe 1 cm from the north wall was pushed through
    // it and saw the sky and the wall's sunlit outside (mean ray radiance 5.8 against the room's
    // 0.1; docs/gi.md, energy). The camera sees the probe, so it lies on the probe's side of every
    // wall beside it, and the origin moves only towards the camera's side along each axis: the
    // field's gain one step that way, per axis, gives the push. A central gradient has no side on a
    // wall's plane: at 1080p (low) a probe where two walls and the roof meet had its origin on the
    // side wall's plane, the gradient's component across it was zero, and the push only moved it
    // down the plane; 31 of its 32 rays read the outside (docs/gi.md, energy 25.).
    const float clearance = 0.5 * gSp.originBias;
    const float3 towardCamera = normalize(gSp.camera.position - p.positionAndDepth.xyz);
    const float3 cameraSide = float3(towardCamera.x >= 0.0 ? 1.0 : -1.0, towardCamera.y >= 0.0 ? 1.0 : -1.0,
                                     towardCamera.z >= 0.0 ? 1.0 : -1.0);
    for (uint step = 0u; step < LUMINA_SP_ORIGIN_PUSH_STEPS; ++step) {
        const float distance = sdfSampleGlobal(origin);
        if (distance >= clearance) {
            break;
        }
        const float3 gain = max(float3(sdfSampleGlobal(origin + float3(cameraSide.x * clearance, 0.0, 0.0)),
                                       sdfSampleGlobal(origin + float3(0.0, cameraSide.y * clearance, 0.0)),
                                       sdfSampleGlobal(origin + float3(0.0, 0.0, cameraSide.z * clearance))) -
                                    distance,
                                0.0);
        const float3 push = any(gain > 0.0) ? cameraSide * normalize(gain) : towardCamera;
        origin += push * (clearance - distance);
    }
    return origin;
}

// Where one ray of a probe starts: slid from the origin along the probe's surface onto the line
// through the probe's own point (surface_line_start.hlsli), keeping half the push's clearance free.
// From the origin, two voxels up, every ray saw the scene as from a point two voxels into the room:
// two_rooms read 3.5 % bright (docs/gi.md, energy 21.). Both fields start a ray here, so the far
// field continues the line the near field covered.
float3 probeRayStart(ScreenProbe p, float3 origin, float3 direction) {
    return surfaceLineStart(origin, p.positionAndDepth.xyz, p.normal.xyz, direction,
                            dot(direction, p.normal.xyz), gSp.slideMarginVoxels);
}

groupshared float3 gsRayOrigin;

// The probe a per-probe group traces for and the origin of its rays (probeRayOrigin, the same for
// both fields), found once per group by its first thread: the push samples the global SDF up to
// 17 times (4 a step, then the last test). False, for the whole group alike, when the group has no
// valid probe (sky).
bool tracedProbe(uint3 group, uint thread, out uint probe, out float3 origin) {
    probe = probeIndexOfGroup(group);
    origin = float3(0.0, 0.0, 0.0);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return false;
    }
    if (thread == 0u) {
        gsRayOrigin = probeRayOrigin(gProbes[probe]);
    }
    GroupMemoryBarrierWithGroupSync();
    origin = gsRayOrigin;
    return true;
}

#endif
