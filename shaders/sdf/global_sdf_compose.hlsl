// lumina-kernel: cs main
// Composes bricks of the global SDF from the mesh SDFs under each instance's transform: the
// GPU twin of composeGlobalSdf (gi/sdf/global_sdf.cpp), same culling, same order, same
// clamps, same shells around open volumes (SdfInstanceDesc::worldMax.w) and thin solids
// (thin_solid_shell.hlsli). One 4x4x4 group per brick of the list; each brick carries the
// instances that can reach it (gi/sdf/global_sdf_bricks.h), ascending, so the result never depends on which
// bricks a dispatch holds. Bricks of every cascade share one dispatch (GlobalSdfBrick names its
// cascade).
#include "common/bindings.hlsli"
#include "common/sdf_scene_shared.h"
#include "common/sdf_shared.h"

LUMINA_PUSH_CONSTANTS(GlobalSdfComposeConstants, gConstants);
ConstantBuffer<SdfSceneInfo> gSdfScene : register(b0);
Texture3D<float> gSdfAtlas : register(t0);
StructuredBuffer<SdfVolumeDesc> gSdfVolumes : register(t1);
StructuredBuffer<SdfInstanceDesc> gSdfInstances : register(t2);
StructuredBuffer<GlobalSdfBrick> gBricks : register(t3);
StructuredBuffer<uint> gBrickInstances : register(t4);
SamplerState gLinearClamp : register(s0);
LUMINA_UAV_FORMAT(rg32f) RWTexture3D<float2> gGlobalSdf : register(u0);

#define LUMINA_SDF_ATLAS gSdfAtlas
#define LUMINA_SDF_SAMPLER gLinearClamp
#include "common/sdf_sampling.hlsli"
#include "common/sdf_tracing.hlsli"
#include "sdf/thin_solid_shell.hlsli"

static const uint kBrickCoordBits = 10u;
static const uint kBrickCoordMask = (1u << kBrickCoordBits) - 1u;

[numthreads(LUMINA_SDF_BRICK_SIZE, LUMINA_SDF_BRICK_SIZE, LUMINA_SDF_BRICK_SIZE)] void main(
    uint3 groupId : SV_GroupID, uint3 threadId : SV_GroupThreadID) {
    uint brickIndex = groupId.y * gConstants.groupsPerRow + groupId.x;
    if (brickIndex >= gConstants.brickCount) {
        return;
    }
    uint4 brick = gBricks[brickIndex].coordAndInstances;
    SdfGlobalCascade cascade = gSdfScene.cascades[brick.w];
    uint3 brickCoord = uint3(brick.x & kBrickCoordMask, (brick.x >> kBrickCoordBits) & kBrickCoordMask,
                             brick.x >> (2u * kBrickCoordBits));
    uint3 voxel = brickCoord * LUMINA_SDF_BRICK_SIZE + threadId;
    if (any(voxel >= cascade.dims)) {
        return;
    }
    float voxelSize = cascade.voxelSize;
    float maxDistance = cascade.maxDistance;
    // The centre from the lattice index, not from the window, so that a voxel recomposed after
    // the window moved equals a fresh compose (for a single cascade: the grid's corner + voxel).
    float3 p = cascade.latticeOrigin + (float3(int3(voxel) + asint(cascade.window)) + 0.5f) * voxelSize;
    float thinHalfThickness = LUMINA_SDF_THIN_SOLID_HALF_THICKNESS_VOXELS * voxelSize;
    float best = maxDistance;
    float bestInstance = LUMINA_SDF_GLOBAL_NO_INSTANCE;
    for (uint i = brick.y; i < brick.y + brick.z; ++i) {
        uint index = gBrickInstances[i];
        SdfInstanceDesc instance = gSdfInstances[index];
        SdfVolumeDesc volume = gSdfVolumes[instance.ids.x];
        // The table's shell is sized for the finest cascade; coarser ones grow it.
        float shell = instance.worldMax.w;
        if (shell > 0.0f) {
            shell += cascade.openShellExtra;
        }
        // A closed volume may get a thin solid's shell instead, at most thinHalfThickness.
        bool closed = (volume.dims.w & LUMINA_SDF_VOLUME_OPEN) == 0u;
        float cullShell = closed ? thinHalfThickness : shell;
        // Everything of the instance lies in its world box: it cannot be nearer.
        float boxDistance = sdfBoxDistance(p, instance.worldMinAndScale.xyz, instance.worldMax.xyz);
        if (boxDistance - cullShell >= best) {
            continue;
        }
        float scale = instance.worldMinAndScale.w;
        float3 local = sdfWorldToObject(instance, p);
        float sampled = sdfSampleVolume(volume, gSdfScene.invAtlasDims, local);
        float d = sampled * scale - shell;
        float weight = closed ? sdfThinSolidShellWeight(d, voxelSize, maxDistance) : 0.0f;
        float thin = 0.0f;
        if (weight > 0.0f && d - thinHalfThickness < best) {
            thin = weight * scale *
                   sdfThinSolidShell(volume, gSdfScene.invAtlasDims, local, sampled, thinHalfThickness / scale);
        }
        // Without a thin shell the box test holds as before (a sample can round below it).
        if (thin == 0.0f && boxDistance - shell >= best) {
            continue;
        }
        d -= thin;
        if (d < best) {
            best = d;
            bestInstance = float(index);
        }
    }
    // Toroidal storage: lattice voxel i at texel i mod dims of the cascade's slab.
    uint3 texel = (voxel + cascade.wrap) % cascade.dims;
    texel.z += cascade.slabFirstZ;
    gGlobalSdf[texel] = float2(max(best, -maxDistance), bestInstance);
}
