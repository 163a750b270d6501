#ifndef LUMINA_SDF_TRACING_HLSLI
#define LUMINA_SDF_TRACING_HLSLI
// The SDF tracing library: what the near field (sdf_near_field.hlsli: per-mesh SDFs of the
// instances a ray can reach, closest hit wins) and the far field (sdf_far_field.hlsli: the
// global SDF, sphere and cone tracing) share. Structs live in sdf_scene_shared.h, so that
// kernels can write SdfHit straight into buffers the C++ side reads.
//
// Rays are world-space, with a unit direction; t is measured from the origin in world units
// and traced over [tMin, params.maxDistance]. A kernel includes the field files it needs
// after naming its resources (see each file's header).
#include "sdf_scene_shared.h"

// Central-difference offset of the normal, in voxels of the traced field: half a voxel
// stays on the near side of thin (unsigned) surfaces that are hit at a few tenths of a
// voxel, yet spans enough of the trilinear cell to average out its kinks.
#define LUMINA_SDF_GRADIENT_STEP_VOXELS 0.5f

SdfTraceParams sdfDefaultTraceParams(float maxDistance) {
    SdfTraceParams params;
    params.minStepVoxels = LUMINA_SDF_DEFAULT_MIN_STEP_VOXELS;
    params.hitThresholdVoxels = LUMINA_SDF_DEFAULT_HIT_THRESHOLD_VOXELS;
    params.maxDistance = maxDistance;
    params.maxSteps = LUMINA_SDF_DEFAULT_MAX_STEPS;
    return params;
}

SdfHit sdfMiss(float3 origin, float3 direction, float t, uint steps) {
    SdfHit hit;
    hit.positionAndT = float4(origin + t * direction, t);
    hit.normalAndCoverage = float4(0.0f, 0.0f, 0.0f, 0.0f);
    hit.ids = uint4(LUMINA_SDF_NO_HIT, LUMINA_SDF_NO_HIT, 1u, steps);
    return hit;
}

bool sdfIsMiss(SdfHit hit) {
    return hit.ids.z != 0u;
}

// The normal a ray sees at its hit, for the lookups that pick a side of the surface (the card
// that owns the hit, the voxel lighting's faces): the SDF gradient, turned to face the ray. An
// open surface's field is unsigned and has no side: at a hit on its plane or past it (a far
// field starting inside its shell, a refined or overshooting step) the gradient can point along
// the ray, and the lookup then read the surface's other side: in sunlit_rooms the shaded room's
// probes read the sunlit outside of the roof and walls (docs/gi.md, energy). A ray that came
// from elsewhere only ever sees a side that faces it. A ray that stopped where it started
// (t = 0: its origin lies within a surface's shell, as radiosity probes in a room's corner do)
// keeps the gradient: that names the side its origin is on. Where the gradient vanished, the
// reversed ray.
float3 sdfFacingNormal(float3 gradientNormal, float3 direction, float t) {
    const float3 n = dot(gradientNormal, gradientNormal) > 0.0f ? gradientNormal : -direction;
    return t > 0.0f && dot(n, direction) > 0.0f ? -n : n;
}

// The direction a hit was seen from, for lookups that skip what the ray cannot see (the voxel
// lighting's faces): the ray's, or zero (see everything) for a ray that stopped where it started.
float3 sdfSeenFrom(float3 direction, float t) {
    return t > 0.0f ? direction : float3(0.0f, 0.0f, 0.0f);
}

float3 sdfWorldToObject(SdfInstanceDesc instance, float3 p) {
    float4 q = float4(p, 1.0f);
    return float3(dot(instance.worldToObject[0], q), dot(instance.worldToObject[1], q),
                  dot(instance.worldToObject[2], q));
}

float3 sdfWorldToObjectVector(SdfInstanceDesc instance, float3 v) {
    return float3(dot(instance.worldToObject[0].xyz, v), dot(instance.worldToObject[1].xyz, v),
                  dot(instance.worldToObject[2].xyz, v));
}

// An object-space gradient to a unit world normal: through the inverse transpose of the
// object-to-world matrix, i.e. the transpose of world-to-object.
float3 sdfObjectGradientToWorldNormal(SdfInstanceDesc instance, float3 g) {
    float3 n = g.x * instance.worldToObject[0].xyz + g.y * instance.worldToObject[1].xyz +
               g.z * instance.worldToObject[2].xyz;
    float len = length(n);
    return len > 0.0f ? n / len : float3(0.0f, 0.0f, 0.0f);
}

// Most a hit refinement moves a hit, in voxels: past a plane met at grazing angle the true
// crossing can lie several voxels on, but a bent surface makes the linear model unreliable.
#define LUMINA_SDF_MAX_REFINE_VOXELS 2.0f
// Slopes flatter than this (distance per unit t) are not extrapolated.
#define LUMINA_SDF_MIN_REFINE_SLOPE 0.02f

// A sphere trace stops where the distance first falls below the hit threshold, up to
// threshold / cos(angle to the normal) short of the surface: several voxels for grazing rays.
// The last two samples give the distance's slope along the ray (exactly -cos(angle) near a
// plane), and the hit may move to where the line through them reaches zero, by at most
// LUMINA_SDF_MAX_REFINE_VOXELS. Callers keep the move only where the field confirms it (the
// distance there is no larger than at the stop), and only on signed surfaces: an unsigned
// one has no zero crossing to find.
float sdfRefineHit(float previousT, float previousDistance, float t, float distance, float voxel) {
    float slope = (distance - previousDistance) / max(t - previousT, 1e-30f);
    if (slope > -LUMINA_SDF_MIN_REFINE_SLOPE) {
        return t;
    }
    return t + min(max(distance, 0.0f) / -slope, LUMINA_SDF_MAX_REFINE_VOXELS * voxel);
}

// Distance from p to a box (0 inside).
float sdfBoxDistance(float3 p, float3 boxMin, float3 boxMax) {
    return length(max(max(boxMin - p, float3(0.0f, 0.0f, 0.0f)), p - boxMax));
}

#endif
