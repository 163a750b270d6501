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

// Thin solids in the global SDF (gi/sdf/global_sdf.h, thinSolidShell): where a closed mesh is
// less deep than this many global voxels (a slab thinner than one voxel), its distances there
// drop by what is missing, so that every global voxel next to it can go negative and the far
// field cannot cross it. Thicker solids keep their distance.
#define LUMINA_SDF_THIN_SOLID_HALF_THICKNESS_VOXELS 0.5f
// The depth is looked for from the nearest surface point down the field's gradient, in at most
// this many steps of a quarter of that half thickness each (three half thicknesses: at a box's
// corner the walk starts along the diagonal, and trilinear samples round the corner).
#define LUMINA_SDF_THIN_SOLID_STEPS 12u
// The shell applies in full up to this many global voxels from the solid and fades to nothing
// over as many more; beyond, the nearest-point estimate of the mesh SDF's lower bound grows too
// rough to judge the depth, and the far field's steps do not need it.
#define LUMINA_SDF_THIN_SOLID_BAND_VOXELS 2.0f
// Where the field at the voxel is steeper than this (a distance changes by at most what one
// moves), it is the sign flip of a solid's missing face, not a thin part: no shell.
#define LUMINA_SDF_THIN_SOLID_MAX_SLOPE 1.5f

// Per-dispatch facts about the atlas texture, for whoever samples it.
struct SdfAtlasInfo {
    float4 invAtlasDims; // xyz: 1 / atlas texels per axis; w: 0
    uint4 counts;        // x: volume count; yzw: 0
};

// How much of a thin solid's shell a global voxel takes at world distance `distance` from the
// solid (unshelled), in a grid of voxel size `voxelSize` truncated at `maxDistance`: 1 within the
// band, falling linearly to 0 over the next band's width, and 0 from the truncation on, so that
// a shell never reaches beyond where the solid can change a voxel (global_sdf_bricks.h).
LUMINA_INLINE float sdfThinSolidShellWeight(float distance, float voxelSize, float maxDistance) {
    float fadeEnd = min(2.0f * LUMINA_SDF_THIN_SOLID_BAND_VOXELS * voxelSize, maxDistance);
    float weight = (fadeEnd - distance) / (LUMINA_SDF_THIN_SOLID_BAND_VOXELS * voxelSize);
    return min(max(weight, 0.0f), 1.0f);
}

LUMINA_STATIC_ASSERT_SIZE(SdfVolumeDesc, 64);
LUMINA_STATIC_ASSERT_SIZE(SdfAtlasInfo, 32);

LUMINA_GPU_NAMESPACE_END

#endif
