#ifndef LUMINA_SDF_NEAR_FIELD_HLSLI
#define LUMINA_SDF_NEAR_FIELD_HLSLI
// Near-field tracing: sphere tracing through the per-mesh SDFs of the instances a ray can
// reach, found through the instance BVH (gi/sdf/instance_bvh.h); the closest hit wins.
// Each instance is traced in its object space (the ray transformed by world-to-object), so
// rotated and scaled instances cost nothing extra and thresholds stay in the mesh's voxels.
//
// The includer names its resources first:
//
//   ConstantBuffer<SdfSceneInfo> gSdfScene : register(b0);
//   Texture3D<float> gSdfAtlas : register(t0);
//   StructuredBuffer<SdfVolumeDesc> gSdfVolumes : register(t1);
//   StructuredBuffer<SdfInstanceDesc> gSdfInstances : register(t2);
//   StructuredBuffer<BvhNode> gSdfInstanceNodes : register(t3);
//   StructuredBuffer<uint> gSdfInstanceList : register(t4);
//   SamplerState gLinearClamp : register(s0);
//   #define LUMINA_SDF_ATLAS gSdfAtlas
//   #define LUMINA_SDF_SAMPLER gLinearClamp
//   #define LUMINA_SDF_SCENE gSdfScene
//   #define LUMINA_SDF_VOLUME(i) gSdfVolumes[i]
//   #define LUMINA_SDF_INSTANCE(i) gSdfInstances[i]
//   #define LUMINA_SDF_INSTANCE_NODE(i) gSdfInstanceNodes[i]
//   #define LUMINA_SDF_INSTANCE_LIST(i) gSdfInstanceList[i]
//   #include "common/sdf_near_field.hlsli"
#include "bvh_shared.h"
#include "ray_box.hlsli"
#include "sdf_sampling.hlsli"
#include "sdf_tracing.hlsli"

#if !defined(LUMINA_SDF_SCENE) || !defined(LUMINA_SDF_VOLUME) || !defined(LUMINA_SDF_INSTANCE) ||                 \
    !defined(LUMINA_SDF_INSTANCE_NODE) || !defined(LUMINA_SDF_INSTANCE_LIST)
#error "define LUMINA_SDF_SCENE, LUMINA_SDF_VOLUME, LUMINA_SDF_INSTANCE, LUMINA_SDF_INSTANCE_NODE and LUMINA_SDF_INSTANCE_LIST before including sdf_near_field.hlsli"
#endif

// Median-split instance BVHs are at most ceil(log2(n)) + 1 levels deep: 32 entries cover
// any instance count the 32-bit ids allow.
#define LUMINA_SDF_INSTANCE_STACK_SIZE 32
// The least rate at which an open surface's distance falls along a ray that the band of an open
// hit assumes (a ray 6 degrees off the sheet's plane): bands stay within ten thresholds.
#define LUMINA_SDF_OPEN_BAND_MIN_RATE 0.1f

// The best hit so far of a near-field trace, in the frame of the instance that made it.
//
// An open (unsigned) surface is hit as soon as the ray comes within its threshold, which is
// 0.6 of its own voxels: where along the ray the sheet really is stays unknown over a band of
// threshold / (the rate at which the distance falls along the ray) beyond the hit, ten
// thresholds on grazing rays. So another instance whose surface the ray meets within that band,
// with a finer threshold, is the better answer: the surface the ray reaches first, or the same
// sheet's neighbour known more sharply. `reach` keeps the segment open that far. This is what let
// `two_rooms`' emissive panel, filling a hole in the ceiling of the room's shell (an open mesh
// with 13 cm voxels), hide behind the shell's band around the hole's rim, for the rays that see
// it at a slant (docs/gi.md, 33.).
struct SdfNearFieldState {
    float t;            // world units; the end of the traced segment while nothing was hit
    uint instance;      // LUMINA_SDF_NO_HIT while nothing was hit
    float3 objectPoint; // hit point in the instance's object space
    uint steps;         // summed over every instance traced
    float threshold;    // the hit's threshold in world units (its sharpness); 0 while nothing was hit
    float reach;        // world t up to which a sharper hit may still replace this one (>= t)
};

// Whether a hit at world t with world threshold `threshold` and band end `reach` replaces the
// best so far: the nearer one, unless the other is sharper and lies within the nearer one's band.
bool sdfNearFieldHitWins(float t, float threshold, float reach, SdfNearFieldState state) {
    if (state.instance == LUMINA_SDF_NO_HIT) {
        return t <= state.t;
    }
    if (t < state.t) {
        return !(state.t <= reach && state.threshold < threshold);
    }
    return t <= state.reach && threshold < state.threshold;
}

// Sphere traces one instance over world t in [tMin, state.reach]; a hit that wins
// (sdfNearFieldHitWins) replaces the one in `state`.
void sdfTraceInstance(uint instanceIndex, float3 origin, float3 direction, float tMin, SdfTraceParams params,
                      inout SdfNearFieldState state) {
    SdfInstanceDesc instance = LUMINA_SDF_INSTANCE(instanceIndex);
    // Leaves hold several instances: skip those whose own world box the segment misses.
    if (intersectBox(origin, safeReciprocal3(direction), instance.worldMinAndScale.xyz, instance.worldMax.xyz,
                     tMin, state.reach) < 0.0f) {
        return;
    }
    SdfVolumeDesc volume = LUMINA_SDF_VOLUME(instance.ids.x);
    float3 o = sdfWorldToObject(instance, origin);
    float3 dScaled = sdfWorldToObjectVector(instance, direction);
    // Object units per world unit along this ray: exact for any affine transform.
    float scale = length(dScaled);
    if (!(scale > 0.0f)) {
        return;
    }
    float3 d = dScaled / scale;
    float2 range = boxEntryExit(o, safeReciprocal3(d), volume.volumeMinAndVoxelSize.xyz,
                                volume.volumeMaxAndInvVoxelSize.xyz);
    float t = max(range.x, tMin * scale);
    float tExit = min(range.y, state.reach * scale);
    if (!(t <= tExit)) {
        return;
    }
    float3 invAtlasDims = LUMINA_SDF_SCENE.invAtlasDims;
    float voxel = volume.volumeMinAndVoxelSize.w;
    bool open = (volume.dims.w & LUMINA_SDF_VOLUME_OPEN) != 0u;
    float threshold = (open ? max(params.hitThresholdVoxels, LUMINA_SDF_OPEN_SURFACE_THRESHOLD_VOXELS)
                            : params.hitThresholdVoxels) *
                      voxel;
    float minStep = params.minStepVoxels * voxel;
    float previousT = -1.0f;
    float previousDistance = 0.0f;
    for (uint step = 0u; step < params.maxSteps; ++step) {
        state.steps += 1u;
        float distance = sdfSampleVolume(volume, invAtlasDims, o + t * d);
        if (distance < threshold) {
            // A signed surface lies ahead where the distance reaches zero: move there (see
            // sdfRefineHit); open volumes have no zero crossing to find.
            if (!open && previousT >= 0.0f) {
                float refined = min(sdfRefineHit(previousT, previousDistance, t, distance, voxel), tExit);
                if (refined > t && abs(sdfSampleVolume(volume, invAtlasDims, o + refined * d)) <= distance) {
                    t = refined;
                }
            }
            // An open hit's band: where the sheet lies along the ray, from the rate at which the
            // distance fell over the last step (exact for a plane; one threshold when the
            // first sample hit).
            float rate = previousT >= 0.0f ? (previousDistance - distance) / (t - previousT) : 1.0f;
            float band = open ? threshold / clamp(rate, LUMINA_SDF_OPEN_BAND_MIN_RATE, 1.0f) : 0.0f;
            float hitT = t / scale;
            float hitThreshold = threshold / scale;
            float hitReach = min((t + band) / scale, params.maxDistance);
            if (sdfNearFieldHitWins(hitT, hitThreshold, hitReach, state)) {
                state.t = hitT;
                state.instance = instanceIndex;
                state.objectPoint = o + t * d;
                state.threshold = hitThreshold;
                state.reach = max(hitReach, hitT);
            }
            return;
        }
        previousT = t;
        previousDistance = distance;
        t += max(distance, minStep);
        if (t > tExit) {
            return;
        }
    }
}

// Unit world normal of an instance's surface at an object-space point, from the central
// differences of its mesh SDF.
float3 sdfInstanceNormal(uint instanceIndex, float3 objectPoint) {
    SdfInstanceDesc instance = LUMINA_SDF_INSTANCE(instanceIndex);
    SdfVolumeDesc volume = LUMINA_SDF_VOLUME(instance.ids.x);
    float3 invAtlasDims = LUMINA_SDF_SCENE.invAtlasDims;
    float h = LUMINA_SDF_GRADIENT_STEP_VOXELS * volume.volumeMinAndVoxelSize.w;
    float3 g;
    g.x = sdfSampleVolume(volume, invAtlasDims, objectPoint + float3(h, 0.0f, 0.0f)) -
          sdfSampleVolume(volume, invAtlasDims, objectPoint - float3(h, 0.0f, 0.0f));
    g.y = sdfSampleVolume(volume, invAtlasDims, objectPoint + float3(0.0f, h, 0.0f)) -
          sdfSampleVolume(volume, invAtlasDims, objectPoint - float3(0.0f, h, 0.0f));
    g.z = sdfSampleVolume(volume, invAtlasDims, objectPoint + float3(0.0f, 0.0f, h)) -
          sdfSampleVolume(volume, invAtlasDims, objectPoint - float3(0.0f, 0.0f, h));
    return sdfObjectGradientToWorldNormal(instance, g);
}

// The nearest hit over every instance whose world box the ray overlaps in
// [tMin, params.maxDistance]. Nearer BVH children are visited first, and a subtree entered
// beyond the best hit so far is skipped.
SdfHit sdfTraceNearField(float3 origin, float3 direction, float tMin, SdfTraceParams params) {
    SdfNearFieldState state;
    state.t = params.maxDistance;
    state.instance = LUMINA_SDF_NO_HIT;
    state.objectPoint = float3(0.0f, 0.0f, 0.0f);
    state.steps = 0u;
    state.threshold = 0.0f;
    state.reach = params.maxDistance;
    if (LUMINA_SDF_SCENE.instanceBvhNodeCount != 0u) {
        float3 invDir = safeReciprocal3(direction);
        uint stackNode[LUMINA_SDF_INSTANCE_STACK_SIZE];
        float stackEntry[LUMINA_SDF_INSTANCE_STACK_SIZE];
        uint stackSize = 0u;
        BvhNode root = LUMINA_SDF_INSTANCE_NODE(0u);
        float rootEntry =
            intersectBox(origin, invDir, root.minAndIndex.xyz, root.maxAndCount.xyz, tMin, state.reach);
        if (rootEntry >= 0.0f) {
            stackNode[0] = 0u;
            stackEntry[0] = rootEntry;
            stackSize = 1u;
        }
        while (stackSize > 0u) {
            stackSize -= 1u;
            uint node = stackNode[stackSize];
            if (stackEntry[stackSize] > state.reach) {
                continue;
            }
            for (;;) {
                BvhNode n = LUMINA_SDF_INSTANCE_NODE(node);
                uint count = asuint(n.maxAndCount.w);
                uint index = asuint(n.minAndIndex.w);
                if (count != 0u) {
                    for (uint i = index; i < index + count; ++i) {
                        sdfTraceInstance(LUMINA_SDF_INSTANCE_LIST(i), origin, direction, tMin, params, state);
                    }
                    break;
                }
                uint left = node + 1u;
                uint right = index;
                BvhNode l = LUMINA_SDF_INSTANCE_NODE(left);
                BvhNode r = LUMINA_SDF_INSTANCE_NODE(right);
                float tLeft =
                    intersectBox(origin, invDir, l.minAndIndex.xyz, l.maxAndCount.xyz, tMin, state.reach);
                float tRight =
                    intersectBox(origin, invDir, r.minAndIndex.xyz, r.maxAndCount.xyz, tMin, state.reach);
                if (tLeft >= 0.0f && tRight >= 0.0f) {
                    bool leftFirst = tLeft <= tRight;
                    if (stackSize < LUMINA_SDF_INSTANCE_STACK_SIZE) {
                        stackNode[stackSize] = leftFirst ? right : left;
                        stackEntry[stackSize] = leftFirst ? tRight : tLeft;
                        stackSize += 1u;
                    }
                    node = leftFirst ? left : right;
                } else if (tLeft >= 0.0f) {
                    node = left;
                } else if (tRight >= 0.0f) {
                    node = right;
                } else {
                    break;
                }
            }
        }
    }
    if (state.instance == LUMINA_SDF_NO_HIT) {
        return sdfMiss(origin, direction, state.t, state.steps);
    }
    SdfInstanceDesc instance = LUMINA_SDF_INSTANCE(state.instance);
    SdfHit hit;
    hit.positionAndT = float4(origin + state.t * direction, state.t);
    hit.normalAndCoverage = float4(sdfInstanceNormal(state.instance, state.objectPoint), 0.0f);
    hit.ids = uint4(instance.ids.z, instance.ids.y, 0u, state.steps);
    return hit;
}

#endif
