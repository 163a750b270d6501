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

// The best hit so far of a near-field trace, in the frame of the instance that made it.
struct SdfNearFieldState {
    float t;            // world units; the end of the traced segment while nothing was hit
    uint instance;      // LUMINA_SDF_NO_HIT while nothing was hit
    float3 objectPoint; // hit point in the instance's object space
    uint steps;         // summed over every instance traced
};

// Sphere traces one instance over world t in [tMin, state.t]; a nearer hit replaces the one
// in `state`.
void sdfTraceInstance(uint instanceIndex, float3 origin, float3 direction, float tMin, SdfTraceParams params,
                      inout SdfNearFieldState state) {
    SdfInstanceDesc instance = LUMINA_SDF_INSTANCE(instanceIndex);
    // Leaves hold several instances: skip those whose own world box the segment misses.
    if (intersectBox(origin, safeReciprocal3(direction), instance.worldMinAndScale.xyz, instance.worldMax.xyz, tMin,
                     state.t) < 0.0f) {
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
    float tExit = min(range.y, state.t * scale);
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
            state.t = t / scale;
            state.instance = instanceIndex;
            state.objectPoint = o + t * d;
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
    if (LUMINA_SDF_SCENE.instanceBvhNodeCount != 0u) {
        float3 invDir = safeReciprocal3(direction);
        uint stackNode[LUMINA_SDF_INSTANCE_STACK_SIZE];
        float stackEntry[LUMINA_SDF_INSTANCE_STACK_SIZE];
        uint stackSize = 0u;
        BvhNode root = LUMINA_SDF_INSTANCE_NODE(0u);
        float rootEntry = intersectBox(origin, invDir, root.minAndIndex.xyz, root.maxAndCount.xyz, tMin, state.t);
        if (rootEntry >= 0.0f) {
            stackNode[0] = 0u;
            stackEntry[0] = rootEntry;
            stackSize = 1u;
        }
        while (stackSize > 0u) {
            stackSize -= 1u;
            uint node = stackNode[stackSize];
            if (stackEntry[stackSize] > state.t) {
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
                float tLeft = intersectBox(origin, invDir, l.minAndIndex.xyz, l.maxAndCount.xyz, tMin, state.t);
                float tRight = intersectBox(origin, invDir, r.minAndIndex.xyz, r.maxAndCount.xyz, tMin, state.t);
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
