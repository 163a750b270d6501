#ifndef LUMINA_SDF_SHARED_H
#define LUMINA_SDF_SHARED_H
// GPU layout of the mesh SDF atlas (gi/sdf/): every mesh's distance volume is a box of voxels
// inside one 3D texture (lavapipe has no descriptor indexing, so no texture arrays), found
// through a table of SdfVolumeDesc, one per mesh, in a structured buffer.
//
// Conventions (gi/sdf/mesh_sdf.h has the details):
// - Voxel (i, j, k) of a volume holds the signed distance at its centre,
//   volumeMin + (i + 0.5, j + 0.5, k + 0.5) * voxelSize, in mesh space; negative inside.
// - Atlas texels hold that distance in voxels (distance / voxelSize), R16F or R32F; multiply
//   by voxelSize for mesh units. Voxel units keep half floats far from overflow at any scale.
// - Volumes are packed without gaps: samplers clamp the local voxel coordinate to
//   [0.5, dims - 0.5] so that trilinear filtering never reads a neighbour.
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct SdfVolumeDesc {
    float4 volumeMinAndVoxelSize;    // xyz: mesh-space corner of voxel (0,0,0); w: voxel size
    float4 volumeMaxAndInvVoxelSize; // xyz: mesh-space far corner (volumeMin + dims * voxelSize); w: 1 /
                                     // voxel size
    uint4 atlasOffset;               // xyz: atlas texel holding voxel (0,0,0); w: 0
    uint4 dims;                      // xyz: voxels per axis; w: flags (LUMINA_SDF_VOLUME_OPEN)
};

// The mesh is open: it has boundary edges (a quad, a drape, walls without a floor) or no
// negative voxel at all. Open surfaces are stored unsigned (gi/sdf/mesh_sdf.h), and their
// trilinear samples need not fall below half a voxel on the surface, so tracers hit them with a
// thicker threshold (sdf_near_field.hlsli) and the global SDF gives them a shell
// (gi/sdf/global_sdf.h).
#define LUMINA_SDF_VOLUME_OPEN 1u
// Hit threshold, in voxels, of open volumes: on a plane midway between voxel centres the
// trilinear value of the unsigned distance is half a voxel (the worst case; a plane tilted
// through a cell gives less), plus a margin for R16F rounding and hardware filter weights.
#define LUMINA_SDF_OPEN_SURFACE_THRESHOLD_VOXELS 0.6f
// Shell of an open volume in the global SDF: this many global voxels plus
// LUMINA_SDF_OPEN_SURFACE_THRESHOLD_VOXELS of the mesh's own (gi/sdf/global_sdf.h).
#define LUMINA_SDF_OPEN_SURFACE_GLOBAL_SHELL_VOXELS 0.5f

// Per-dispatch facts about the atlas texture, for whoever samples it.
struct SdfAtlasInfo {
    float4 invAtlasDims; // xyz: 1 / atlas texels per axis; w: 0
    uint4 counts;        // x: volume count; yzw: 0
};

LUMINA_STATIC_ASSERT_SIZE(SdfVolumeDesc, 64);
LUMINA_STATIC_ASSERT_SIZE(SdfAtlasInfo, 32);

LUMINA_GPU_NAMESPACE_END

#endif
