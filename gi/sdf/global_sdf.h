#pragma once
// The global SDF composition, CPU reference: signed distance to the nearest instance and
// that instance's id over a world-space grid, from the mesh SDF atlas and the instance
// transforms. The GPU pass of issue 10 computes the same thing and is tested against this.
//
// Per voxel centre p: for each instance whose world box could hold something nearer than the
// best so far, d = sampleSdf(atlas, volume, meshToWorld^-1 p) * scale, where scale is the
// smallest column length of the 3x3 part of meshToWorld (exact for rotation + uniform scale;
// for non-uniform scale an estimate of the distance, good near surfaces). The union is the
// minimum; distances are clamped to [-maxDistance, maxDistance], and voxels with nothing
// within maxDistance get kNoInstance. Inside an instance's volume its distance is the mesh
// SDF's; beyond every volume the value is a lower bound (sampleSdf), so the instance named
// there is the one with the smallest bound, not always the nearest.
//
// Open volumes (LUMINA_SDF_VOLUME_OPEN, e.g. a quad, stored unsigned) contribute d - shell
// (openSurfaceShell): an unsigned plane between two voxel centres reads up to half a voxel on
// the plane, of the mesh SDF and again of the global grid, so without a shell a tracer could
// pass through it. With shell = 0.5 global voxel + 0.6 mesh voxel (world units), both grid
// voxels next to the surface are negative: a zero crossing any tracer finds. The surface
// thickens by the shell; the culling test accounts for it.
//
// Thin solids: a closed volume's field is signed, but where the solid is thinner than a global
// voxel (a 4 cm door in a grid of 13 cm voxels) no voxel centre need fall inside it, so the grid
// never goes negative there and the far field walks through. So closed volumes contribute
// d - w * thinSolidShell, where the solid is less than LUMINA_SDF_THIN_SOLID_HALF_THICKNESS_VOXELS
// (half a global voxel) deep near the voxel: the shell makes up the missing depth, so the
// solid is one voxel thick to the grid, and w (sdfThinSolidShellWeight) keeps it to the voxels
// within a few voxels of the solid. Solids at least a voxel thick get no shell and keep their
// true distance (a shell on every solid narrowed doorways; docs/gi.md, energy). The culling test
// allows for the largest shell, half a voxel.
#include "gi/sdf/sdf_atlas.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::sdf {

inline constexpr uint32_t kNoInstance = 0xFFFFFFFFu;

struct SdfInstance {
    glm::mat4 meshToWorld{1.0f}; // affine
    uint32_t volume = 0;         // index into SdfAtlas::volumes
};

struct GlobalSdfSettings {
    glm::vec3 boundsMin{0.0f}; // corner of voxel (0,0,0); centres at boundsMin + (i + 0.5) * voxelSize
    float voxelSize = 1.0f;
    glm::uvec3 dims{32};
    float maxDistance = 1e30f;
    uint32_t threads = 0; // 0: hardware concurrency
    // A cascade coarser than the finest (gi/sdf/global_sdf_cascades.h) grows open instances'
    // shells by this much beyond SdfInstanceDesc::worldMax.w, which is sized for the finest.
    // composeGlobalSdf sizes shells from voxelSize itself and does not read it.
    float openShellExtra = 0.0f;
};

struct GlobalSdf {
    glm::uvec3 dims{0};
    glm::vec3 boundsMin{0.0f};
    float voxelSize = 0.0f;
    std::vector<float> distances;    // world units, x fastest
    std::vector<uint32_t> instances; // nearest instance (index into the span given), or kNoInstance

    size_t voxelIndex(uint32_t x, uint32_t y, uint32_t z) const {
        return (size_t(z) * dims.y + y) * dims.x + x;
    }
    glm::vec3 voxelCentre(uint32_t x, uint32_t y, uint32_t z) const {
        return boundsMin + (glm::vec3(x, y, z) + 0.5f) * voxelSize;
    }
};

// The world box of an instance's SDF volume (its eight corners transformed) and its distance
// scale (the smallest column length of the 3x3 part), as composeGlobalSdf computes them; the
// GPU instance table (gi/sdf/scene_sdf_data.h) uses the same functions, so that both cull
// instances alike.
bvh::Aabb instanceWorldBox(const gpu::SdfVolumeDesc& volume, const glm::mat4& meshToWorld);
float instanceDistanceScale(const glm::mat4& meshToWorld);
// The shell (world units) an instance of `volume` with distance scale `distanceScale` gets
// in a global SDF of voxel size `globalVoxelSize`; 0 for closed volumes.
float openSurfaceShell(const gpu::SdfVolumeDesc& volume, float distanceScale, float globalVoxelSize);

// The thin-solid shell (mesh units) at mesh-space point `p` of closed volume `volume`, whose
// sample there is `distance` (mesh units), for the half thickness `halfThickness` (mesh units)
// the global grid needs: max(0, halfThickness + deepest), deepest the lowest sample found from
// the nearest surface point down the field's gradient, until deep enough or out of the solid
// again (see global_sdf.cpp). 0 where the solid is at least halfThickness deep. The compose kernel's
// sdfThinSolidShell (shaders/sdf/thin_solid_shell.hlsli) is its GPU twin.
float thinSolidShell(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p, float distance,
                     float halfThickness);

GlobalSdf composeGlobalSdf(const SdfAtlas& atlas, std::span<const SdfInstance> instances,
                           const GlobalSdfSettings& settings);

} // namespace lumina::sdf
