#ifndef LUMINA_SDF_SCENE_SHARED_H
#define LUMINA_SDF_SCENE_SHARED_H
// GPU layout of a scene's distance fields (gi/sdf/scene_sdf.h), read by the SDF tracing
// library (sdf_tracing.hlsli, sdf_near_field.hlsli, sdf_far_field.hlsli):
//
// - the mesh SDF atlas and its SdfVolumeDesc table (sdf_shared.h);
// - one SdfInstanceDesc per placed mesh, with both transforms and its world box;
// - an instance BVH over those world boxes: BvhNode (bvh_shared.h) laid out depth-first as
//   the triangle BVH is, whose leaves name a range of a uint list of instance indices;
// - the global SDF: an RG32F 3D texture over the scene bounds (or clipmap cascades around the
//   camera, one slab each, SdfGlobalCascade), R the signed distance in
//   world units (truncated to +-maxDistance), G the index of the nearest instance as a float
//   (exact below 2^24), LUMINA_SDF_GLOBAL_NO_INSTANCE where nothing lies within maxDistance.
//   Ids are stored as float values, not as float bits: small integers as bits are
//   denormals, which a GPU may flush.
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_SDF_NO_HIT 0xFFFFFFFFu
#define LUMINA_SDF_GLOBAL_NO_INSTANCE (-1.0f)
// Voxels per side of a global SDF brick: the unit of (incremental) composition, one
// 4x4x4 thread group each.
#define LUMINA_SDF_BRICK_SIZE 4u

struct SdfInstanceDesc {
    float4 worldToObject[3]; // rows of the 3x4 world-to-object matrix
    float4 objectToWorld[3]; // rows of the 3x4 object-to-world matrix
    float4 worldMinAndScale; // xyz: world box of the instance's SDF volume; w: object-to-world
                             // distance scale (smallest column length of the 3x3 part)
    float4 worldMax;         // xyz: world box max; w: shell subtracted from its distances in the global
                             // SDF, world units (openSurfaceShell, gi/sdf/global_sdf.h; 0: closed)
    uint4 ids;               // x: SDF volume; y: scene mesh; z: scene instance; w: 0
};

// Most clipmap cascades of the global SDF (gi/sdf/global_sdf_cascades.h).
#define LUMINA_SDF_MAX_CASCADES 6u

// One cascade of the global SDF: a window of dims voxels on a lattice of voxelSize, stored
// toroidally in its slab of the global SDF texture (slab c: z texels [c * dims.z, (c + 1) * dims.z)).
// A scene with one cascade has the scene-fitted grid: lattice origin = window corner, window 0.
struct SdfGlobalCascade {
    float3 boxMin; // world corner of the window (its voxel (0,0,0))
    float voxelSize;
    float3 boxMax;        // far corner of the window
    float maxDistance;    // truncation distance
    float3 latticeOrigin; // world corner of lattice voxel (0,0,0)
    float openShellExtra; // what open instances' shells (SdfInstanceDesc::worldMax.w, sized for
                          // cascade 0) grow by here
    uint3 window;         // lattice voxel at the window's corner, int bits (asint)
    uint windowPadding;
    uint3 wrap;      // texel of window voxel (0,0,0): window mod dims
    uint slabFirstZ; // first z texel of the cascade's slab
    uint3 dims;      // voxels per axis
    uint dimsPadding;
};

// Facts every kernel that traces the scene's SDFs needs, in one constant buffer. The global*
// fields describe the cascades together: the box is their union, the voxel size and
// truncation the finest cascade's (for a single cascade: the grid's own).
struct SdfSceneInfo {
    float3 invAtlasDims; // 1 / atlas texels per axis
    float invAtlasDimsPadding;
    float3 globalMin;        // world corner of the cascades' union
    float globalVoxelSize;   // the finest cascade's
    float3 globalMax;        // far corner of the union
    float globalMaxDistance; // the finest cascade's truncation distance
    uint3 globalDims;        // voxels per axis of every cascade
    uint cascadeCount;
    uint instanceCount;
    uint instanceBvhNodeCount;
    uint volumeCount;
    uint countsPadding;
    SdfGlobalCascade cascades[LUMINA_SDF_MAX_CASCADES]; // finest first; cascadeCount of them are used
};

// Defaults of SdfTraceParams, after the thesis (at most 64 steps) and the CPU reference
// tracer (gi/sdf/sdf_trace.h: a hit below 0.1 voxel; steps never shorter than that).
#define LUMINA_SDF_DEFAULT_MIN_STEP_VOXELS 0.1f
#define LUMINA_SDF_DEFAULT_HIT_THRESHOLD_VOXELS 0.1f
#define LUMINA_SDF_DEFAULT_MAX_STEPS 64u

// Sphere-tracing parameters (sdf_tracing.hlsli, sdfDefaultTraceParams for the defaults).
// Step and threshold are in voxels of the field being traced (the mesh SDF's own voxels in
// the near field, the global grid's in the far field), so one set fits every scale.
struct SdfTraceParams {
    float minStepVoxels;      // smallest advance per step
    float hitThresholdVoxels; // a hit once the distance falls below this
    float maxDistance;        // world units along the ray (from its origin)
    uint maxSteps;            // per traced field: each instance in the near field, the grid in the far field
};

// One traced ray. On a miss: miss flag 1, ids LUMINA_SDF_NO_HIT, t = params.maxDistance.
struct SdfHit {
    float4 positionAndT;      // xyz: world hit position; w: t along the unit world direction
    float4 normalAndCoverage; // xyz: unit world normal from the SDF gradient; w: cone tracing's
                              // occlusion in [0, 1] (1: fully blocked), 0 for sphere tracing
    uint4 ids;                // x: scene instance; y: scene mesh; z: 1 on a miss, else 0; w: steps
};

// One brick of a compose dispatch and the instances that may reach it: those whose world box
// lies within maxDistance of the brick's box, ascending (the order of the CPU reference).
struct GlobalSdfBrick {
    uint4 coordAndInstances; // x: brick coordinate in its cascade's window, 10 bits per axis
                             // (x | y << 10 | z << 20); y: first entry in the brick instance list;
                             // z: entry count; w: cascade
};

// Push constants of global_sdf_compose.hlsl.
struct GlobalSdfComposeConstants {
    uint brickCount;   // bricks in this dispatch (entries of the brick list)
    uint groupsPerRow; // x groups per dispatch row: brick = groupId.y * groupsPerRow + groupId.x
    uint pad0;
    uint pad1;
};

LUMINA_STATIC_ASSERT_SIZE(SdfInstanceDesc, 144);
LUMINA_STATIC_ASSERT_SIZE(SdfGlobalCascade, 96);
LUMINA_STATIC_ASSERT_OFFSET(SdfGlobalCascade, boxMax, 16);
LUMINA_STATIC_ASSERT_OFFSET(SdfGlobalCascade, latticeOrigin, 32);
LUMINA_STATIC_ASSERT_OFFSET(SdfGlobalCascade, window, 48);
LUMINA_STATIC_ASSERT_OFFSET(SdfGlobalCascade, wrap, 64);
LUMINA_STATIC_ASSERT_OFFSET(SdfGlobalCascade, dims, 80);
LUMINA_STATIC_ASSERT_SIZE(SdfSceneInfo, 80 + 96 * LUMINA_SDF_MAX_CASCADES);
LUMINA_STATIC_ASSERT_OFFSET(SdfSceneInfo, globalMin, 16);
LUMINA_STATIC_ASSERT_OFFSET(SdfSceneInfo, globalMax, 32);
LUMINA_STATIC_ASSERT_OFFSET(SdfSceneInfo, globalDims, 48);
LUMINA_STATIC_ASSERT_OFFSET(SdfSceneInfo, instanceCount, 64);
LUMINA_STATIC_ASSERT_OFFSET(SdfSceneInfo, cascades, 80);
LUMINA_STATIC_ASSERT_SIZE(SdfTraceParams, 16);
LUMINA_STATIC_ASSERT_SIZE(SdfHit, 48);
LUMINA_STATIC_ASSERT_SIZE(GlobalSdfBrick, 16);
LUMINA_STATIC_ASSERT_SIZE(GlobalSdfComposeConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
