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
    uint4 dims;                      // xyz: voxels per axis; w: 0
};

// Per-dispatch facts about the atlas texture, for whoever samples it.
struct SdfAtlasInfo {
    float4 invAtlasDims; // xyz: 1 / atlas texels per axis; w: 0
    uint4 counts;        // x: volume count; yzw: 0
};

LUMINA_STATIC_ASSERT_SIZE(SdfVolumeDesc, 64);
LUMINA_STATIC_ASSERT_SIZE(SdfAtlasInfo, 32);

LUMINA_GPU_NAMESPACE_END

#endif
