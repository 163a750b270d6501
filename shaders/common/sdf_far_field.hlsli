#ifndef LUMINA_SDF_FAR_FIELD_HLSLI
#define LUMINA_SDF_FAR_FIELD_HLSLI
// Far-field tracing through the global SDF (RG32F: distance in world units, truncated to
// +-maxDistance; nearest instance id as a float): sphere tracing, and cone tracing that also
// estimates how much of the cone was blocked.
//
// Cascades (SdfGlobalCascade, gi/sdf/global_sdf_cascades.h): every sample reads the finest
// cascade whose window holds it (sdfGlobalCascadeAt), and the tracers' thresholds and smallest
// steps are in that cascade's voxels; a truncated distance is a safe step in any cascade, so a
// ray walks from fine to coarse cascades without special cases. With one cascade all of this
// is the single scene-fitted grid.
//
// Samples are trilinear from eight Loads, not the hardware filter: filtering 32-bit float
// textures is an optional feature, the G channel (ids) must never be filtered, and exact
// weights keep the GPU within rounding of the CPU reference (composeGlobalSdf).
//
// The includer names its resources first:
//
//   ConstantBuffer<SdfSceneInfo> gSdfScene : register(b0);
//   StructuredBuffer<SdfInstanceDesc> gSdfInstances : register(t2);
//   Texture3D<float2> gGlobalSdf : register(t5);
//   #define LUMINA_SDF_SCENE gSdfScene
//   #define LUMINA_SDF_INSTANCE(i) gSdfInstances[i]
//   #define LUMINA_SDF_GLOBAL gGlobalSdf
//   #include "common/sdf_far_field.hlsli"
#include "ray_box.hlsli"
#include "sdf_tracing.hlsli"

#if !defined(LUMINA_SDF_SCENE) || !defined(LUMINA_SDF_INSTANCE) || !defined(LUMINA_SDF_GLOBAL)
#error "define LUMINA_SDF_SCENE, LUMINA_SDF_INSTANCE and LUMINA_SDF_GLOBAL before including sdf_far_field.hlsli"
#endif

float sdfGlobalTexel(uint3 texel) {
    return LUMINA_SDF_GLOBAL.Load(int4(int3(texel), 0)).x;
}

uint sdfGlobalCascadeCount() {
    return LUMINA_SDF_SCENE.cascadeCount;
}

// The finest cascade whose window holds p at least a voxel from its faces (so that trilinear
// samples and the normal's central differences stay inside it); the coarsest when none does.
uint sdfGlobalCascadeAt(float3 p) {
    uint count = sdfGlobalCascadeCount();
    for (uint c = 0u; c + 1u < count; ++c) {
        SdfGlobalCascade cascade = LUMINA_SDF_SCENE.cascades[c];
        float margin = cascade.voxelSize;
        if (all(p >= cascade.boxMin + margin) && all(p <= cascade.boxMax - margin)) {
            return c;
        }
    }
    return count - 1u;
}

float sdfGlobalVoxelSize(uint cascade) {
    return LUMINA_SDF_SCENE.cascades[cascade].voxelSize;
}

// Voxel size of the cascade that serves p: the scale of the global SDF's detail (and error) there.
float sdfGlobalVoxelSizeAt(float3 p) {
    return sdfGlobalVoxelSize(sdfGlobalCascadeAt(p));
}

// Voxels of the finest cascade in one voxel of the cascade that serves p (1, 2, 4, ...; exactly 1
// with a single cascade): scales offsets chosen in finest voxels, such as a ray origin's lift.
float sdfGlobalCascadeScaleAt(float3 p) {
    return sdfGlobalVoxelSizeAt(p) / sdfGlobalVoxelSize(0u);
}

// Signed distance in world units at a world point, from one cascade. Outside its window: a
// lower bound, sqrt(d^2 + s^2), d the distance to the window and s the sample at its nearest point.
float sdfSampleCascade(uint c, float3 p) {
    SdfGlobalCascade cascade = LUMINA_SDF_SCENE.cascades[c];
    float3 boxMin = cascade.boxMin;
    float3 boxMax = cascade.boxMax;
    float invVoxel = 1.0f / cascade.voxelSize;
    uint3 dims = cascade.dims;
    float3 inBox = clamp(p, boxMin, boxMax);
    // local lies in [0, dims - 1], so floor(local) is a voxel of the grid. Each value is cast to
    // one other type only (dims to float, the floored voxel to uint): vkd3d-shader merges two
    // casts of one value and then reads one as the other (docs/d3d12.md).
    float3 local = clamp((inBox - boxMin) * invVoxel, float3(0.5f, 0.5f, 0.5f), float3(dims) - 0.5f) - 0.5f;
    float3 baseVoxel = floor(local);
    float3 f = local - baseVoxel;
    uint3 base = uint3(baseVoxel);
    uint3 next = min(base + 1u, dims - 1u);
    // Toroidal texels of base and next, (voxel + wrap) mod dims: both terms lie in [0, dims), so
    // one conditional subtraction does it, without an integer division per sample. With a single
    // cascade the wrap is 0: the texels are base and next themselves.
    uint3 b = base + cascade.wrap;
    b = b >= dims ? b - dims : b;
    uint3 n = next + cascade.wrap;
    n = n >= dims ? n - dims : n;
    b.z += cascade.slabFirstZ;
    n.z += cascade.slabFirstZ;
    float c00 = lerp(sdfGlobalTexel(uint3(b.x, b.y, b.z)), sdfGlobalTexel(uint3(n.x, b.y, b.z)), f.x);
    float c10 = lerp(sdfGlobalTexel(uint3(b.x, n.y, b.z)), sdfGlobalTexel(uint3(n.x, n.y, b.z)), f.x);
    float c01 = lerp(sdfGlobalTexel(uint3(b.x, b.y, n.z)), sdfGlobalTexel(uint3(n.x, b.y, n.z)), f.x);
    float c11 = lerp(sdfGlobalTexel(uint3(b.x, n.y, n.z)), sdfGlobalTexel(uint3(n.x, n.y, n.z)), f.x);
    float sample = lerp(lerp(c00, c10, f.y), lerp(c01, c11, f.y), f.z);
    float3 outside = p - inBox;
    float outsideSquared = dot(outside, outside);
    if (outsideSquared > 0.0f) {
        float atBox = max(sample, 0.0f);
        return sqrt(outsideSquared + atBox * atBox);
    }
    return sample;
}

// Signed distance in world units at a world point, from the finest cascade that holds it
// (sdfGlobalCascadeAt); beyond every cascade, the coarsest's lower bound.
float sdfSampleGlobal(float3 p) {
    return sdfSampleCascade(sdfGlobalCascadeAt(p), p);
}

// The instance the global SDF names at the voxel holding p (in the cascade that serves p):
// LUMINA_SDF_NO_HIT where nothing lies within the truncation distance.
uint sdfGlobalInstanceAt(float3 p) {
    SdfGlobalCascade cascade = LUMINA_SDF_SCENE.cascades[sdfGlobalCascadeAt(p)];
    float invVoxel = 1.0f / cascade.voxelSize;
    float3 voxel = clamp(floor((p - cascade.boxMin) * invVoxel), float3(0.0f, 0.0f, 0.0f),
                         float3(cascade.dims - 1u));
    uint3 texel = (uint3(voxel) + cascade.wrap) % cascade.dims;
    texel.z += cascade.slabFirstZ;
    float id = LUMINA_SDF_GLOBAL.Load(int4(int3(texel), 0)).y;
    return id >= 0.0f ? uint(id) : LUMINA_SDF_NO_HIT;
}

// Unit normal from the gradient of the cascade that serves p, half a voxel of it either side.
float3 sdfGlobalNormal(float3 p) {
    uint c = sdfGlobalCascadeAt(p);
    float h = LUMINA_SDF_GRADIENT_STEP_VOXELS * sdfGlobalVoxelSize(c);
    float3 g;
    g.x = sdfSampleCascade(c, p + float3(h, 0.0f, 0.0f)) - sdfSampleCascade(c, p - float3(h, 0.0f, 0.0f));
    g.y = sdfSampleCascade(c, p + float3(0.0f, h, 0.0f)) - sdfSampleCascade(c, p - float3(0.0f, h, 0.0f));
    g.z = sdfSampleCascade(c, p + float3(0.0f, 0.0f, h)) - sdfSampleCascade(c, p - float3(0.0f, 0.0f, h));
    float len = length(g);
    return len > 0.0f ? g / len : float3(0.0f, 0.0f, 0.0f);
}

SdfHit sdfGlobalHit(float3 origin, float3 direction, float t, uint steps, float occlusion) {
    SdfHit hit;
    float3 p = origin + t * direction;
    hit.positionAndT = float4(p, t);
    hit.normalAndCoverage = float4(sdfGlobalNormal(p), occlusion);
    uint instance = sdfGlobalInstanceAt(p);
    hit.ids = uint4(LUMINA_SDF_NO_HIT, LUMINA_SDF_NO_HIT, 0u, steps);
    if (instance != LUMINA_SDF_NO_HIT) {
        SdfInstanceDesc desc = LUMINA_SDF_INSTANCE(instance);
        hit.ids.x = desc.ids.z;
        hit.ids.y = desc.ids.y;
    }
    return hit;
}

// The part [tStart, tEnd] of [tMin, maxDistance] inside the grid box; tStart > tEnd when none.
float2 sdfGlobalSegment(float3 origin, float3 direction, float tMin, float maxDistance) {
    float2 range = boxEntryExit(origin, safeReciprocal3(direction), LUMINA_SDF_SCENE.globalMin,
                                LUMINA_SDF_SCENE.globalMax);
    return float2(max(range.x, tMin), min(range.y, maxDistance));
}

// Sphere tracing of the global SDF, a step at a time: sdfGlobalMarchBegin, then sdfGlobalMarchStep
// while it returns LUMINA_SDF_MARCH_GOING, then sdfGlobalMarchHit. sdfTraceGlobal runs one ray so;
// a kernel that traces several rays per thread can run them one after another in a single loop
// (radiosity.hlsl), so that a thread whose ray ends early starts its next one instead of idling
// beside the longest ray of its neighbours.
#define LUMINA_SDF_MARCH_GOING 0u
#define LUMINA_SDF_MARCH_HIT 1u
#define LUMINA_SDF_MARCH_LEFT 2u         // past the end of its segment: a miss
#define LUMINA_SDF_MARCH_OUT_OF_STEPS 3u // params.maxSteps taken: a miss

struct SdfGlobalMarch {
    float3 origin;
    float3 direction;
    float tEnd;
    float t;
    float previousT;
    float previousDistance;
    uint steps;
};

SdfGlobalMarch sdfGlobalMarchBegin(float3 origin, float3 direction, float tMin, SdfTraceParams params,
                                   out uint status) {
    float2 segment = sdfGlobalSegment(origin, direction, tMin, params.maxDistance);
    SdfGlobalMarch march;
    march.origin = origin;
    march.direction = direction;
    march.tEnd = segment.y;
    march.t = segment.x;
    march.previousT = -1.0f;
    march.previousDistance = 0.0f;
    march.steps = 0u;
    status = !(segment.x <= segment.y) ? LUMINA_SDF_MARCH_LEFT
             : params.maxSteps == 0u   ? LUMINA_SDF_MARCH_OUT_OF_STEPS
                                       : LUMINA_SDF_MARCH_GOING;
    return march;
}

// One sample: a hit once the distance falls below params.hitThresholdVoxels voxels of the cascade
// that serves the sample, moved on to the zero crossing (sdfRefineHit); else a step of the
// distance, at least params.minStepVoxels voxels.
uint sdfGlobalMarchStep(inout SdfGlobalMarch march, SdfTraceParams params) {
    march.steps += 1u;
    float3 p = march.origin + march.t * march.direction;
    uint cascade = sdfGlobalCascadeAt(p);
    float voxel = sdfGlobalVoxelSize(cascade);
    float threshold = params.hitThresholdVoxels * voxel;
    float minStep = params.minStepVoxels * voxel;
    float distance = sdfSampleCascade(cascade, p);
    if (distance < threshold) {
        // Every surface of the global SDF has a zero crossing (open ones their shell).
        if (march.previousT >= 0.0f) {
            float refined = min(
                sdfRefineHit(march.previousT, march.previousDistance, march.t, distance, voxel), march.tEnd);
            if (refined > march.t &&
                abs(sdfSampleGlobal(march.origin + refined * march.direction)) <= distance) {
                march.t = refined;
            }
        }
        return LUMINA_SDF_MARCH_HIT;
    }
    march.previousT = march.t;
    march.previousDistance = distance;
    march.t += max(distance, minStep);
    if (march.t > march.tEnd) {
        return LUMINA_SDF_MARCH_LEFT;
    }
    return march.steps < params.maxSteps ? LUMINA_SDF_MARCH_GOING : LUMINA_SDF_MARCH_OUT_OF_STEPS;
}

// The SdfHit of a march from `origin` along `direction` that ended with `status` at `t` after
// `steps` samples. Normals from the global SDF's gradient; ids from the voxel the hit lies in.
SdfHit sdfGlobalMarchHit(float3 origin, float3 direction, float t, uint steps, uint status,
                         SdfTraceParams params) {
    if (status == LUMINA_SDF_MARCH_HIT) {
        return sdfGlobalHit(origin, direction, t, steps, 0.0f);
    }
    return sdfMiss(origin, direction, params.maxDistance, steps);
}

// Sphere tracing of the global SDF, one ray (sdfGlobalMarchStep).
SdfHit sdfTraceGlobal(float3 origin, float3 direction, float tMin, SdfTraceParams params) {
    uint status;
    SdfGlobalMarch march = sdfGlobalMarchBegin(origin, direction, tMin, params, status);
    while (status == LUMINA_SDF_MARCH_GOING) {
        status = sdfGlobalMarchStep(march, params);
    }
    return sdfGlobalMarchHit(march.origin, march.direction, march.t, march.steps, status, params);
}

// Cone tracing of the global SDF: a cone of half-angle atan(tanHalfAngle) around the ray.
// Hit once the distance falls below the cone's radius t * tanHalfAngle (or the hit
// threshold, whichever is larger). normalAndCoverage.w estimates the occlusion,
// 1 - min over the steps of saturate(distance / radius): 0 when nothing came near the cone,
// towards 1 as surfaces fill it (the estimate of soft-shadow cone tracing). A hit reports
// the occlusion at that point too, so a grazing hit is not a full block.
SdfHit sdfConeTraceGlobal(float3 origin, float3 direction, float tMin, float tanHalfAngle, SdfTraceParams params) {
    float2 segment = sdfGlobalSegment(origin, direction, tMin, params.maxDistance);
    float t = segment.x;
    if (!(t <= segment.y)) {
        return sdfMiss(origin, direction, params.maxDistance, 0u);
    }
    float visibility = 1.0f;
    for (uint step = 0u; step < params.maxSteps; ++step) {
        float3 p = origin + t * direction;
        uint cascade = sdfGlobalCascadeAt(p);
        float voxel = sdfGlobalVoxelSize(cascade);
        float threshold = params.hitThresholdVoxels * voxel;
        float minStep = params.minStepVoxels * voxel;
        float distance = sdfSampleCascade(cascade, p);
        float radius = t * tanHalfAngle;
        if (radius > 0.0f) {
            visibility = min(visibility, saturate(distance / radius));
        }
        if (distance < max(threshold, radius)) {
            if (distance < threshold) {
                visibility = 0.0f;
            }
            return sdfGlobalHit(origin, direction, t, step + 1u, 1.0f - visibility);
        }
        t += max(distance, minStep);
        if (t > segment.y) {
            SdfHit miss = sdfMiss(origin, direction, params.maxDistance, step + 1u);
            miss.normalAndCoverage.w = 1.0f - visibility;
            return miss;
        }
    }
    SdfHit miss = sdfMiss(origin, direction, params.maxDistance, params.maxSteps);
    miss.normalAndCoverage.w = 1.0f - visibility;
    return miss;
}

#endif
