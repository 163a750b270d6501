#pragma once
// Clipmap cascades of the global SDF: for scenes too large for one grid of useful resolution,
// `count` cubic grids of the same voxel count, each with twice the previous one's voxel size,
// centred on the camera (and kept inside the scene's box where they are smaller than it), so
// that the finest voxels lie where the camera looks from.
//
// Every cascade lives on a fixed lattice: world position latticeOrigin + i * voxelSize for
// integer i. A cascade's window is the lattice box [origin, origin + dims) with origin a
// multiple of the brick size, so moving it shifts whole bricks. Voxels are stored
// toroidally: lattice voxel i lives at texel i mod dims of the cascade's slab, so a voxel that
// stays inside the window across a move keeps its texel and its value, and a move recomposes
// only the bricks it exposes (exposedBricks). A voxel's centre is computed from its lattice
// index, never from the window, so a recomposed voxel equals a freshly composed one bit for bit.
//
// A scene whose scene-fitted grid (globalGridFor: `resolution` voxels along its longest axis)
// has voxels no coarser than finestVoxelSize gets a single cascade that *is* that grid (its
// lattice origin is the grid's corner, its window never moves): exactly the global SDF of
// before cascades existed.
#include "gi/bvh/bvh.h"
#include "gi/sdf/global_sdf.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace lumina::sdf {

struct GlobalSdfCascadeLayout {
    uint32_t count = 1;
    glm::uvec3 dims{1};           // voxels of every cascade (cubic unless count == 1)
    float finestVoxelSize = 1.0f; // cascade c: finestVoxelSize * 2^c
    glm::vec3 latticeOrigin{0.0f};
    float maxDistanceVoxels = 8.0f;
    // Windows stay inside this box where they are smaller than it (centred on it where not):
    // the scene's instance boxes grown by the padding of the coarsest cascade.
    bvh::Aabb coverBox;

    float voxelSize(uint32_t cascade) const { return finestVoxelSize * float(1u << cascade); }
    bool scrolls() const { return count > 1; }
};

// The layout for a scene box: one scene-fitted grid (globalGridFor) when its voxel size is at
// most finestVoxelSize or maxCascades is 1; otherwise as many cascades as take the voxel size
// from the fitted one (cubic, resolution^3, the coarsest covering the whole scene) down to
// finestVoxelSize, at most maxCascades (then the finest is coarser than finestVoxelSize).
// Throws std::invalid_argument for bad settings.
GlobalSdfCascadeLayout cascadeLayoutFor(const bvh::Aabb& sceneBox, uint32_t resolution, uint32_t padding,
                                        float maxDistanceVoxels, uint32_t maxCascades, float finestVoxelSize);

// Lattice voxel at the corner of cascade c's window for a camera at `camera`: centred on the
// camera, snapped to whole bricks, moved back inside coverBox along axes where the window is
// smaller than it, centred on coverBox where not. Always 0 for a single cascade.
glm::ivec3 cascadeWindowFor(const GlobalSdfCascadeLayout& layout, uint32_t cascade, const glm::vec3& camera);

// Cascade c's window as a grid (what composeGlobalSdf and the brick tracking take).
GlobalSdfSettings cascadeGrid(const GlobalSdfCascadeLayout& layout, uint32_t cascade,
                              const glm::ivec3& window);

// The bricks of window `to` (one flag per brick, x fastest) whose voxels window `from` did not
// hold: what a move from `from` to `to` must recompose. All of them when the windows do not
// overlap.
std::vector<uint8_t> exposedBricks(const GlobalSdfCascadeLayout& layout, const glm::ivec3& from,
                                   const glm::ivec3& to, uint32_t* count = nullptr);

// Texel of window voxel `voxel` (0 <= voxel < dims) within its cascade's slab: (window +
// voxel) mod dims, per axis.
glm::uvec3 cascadeTexel(const GlobalSdfCascadeLayout& layout, const glm::ivec3& window,
                        const glm::uvec3& voxel);

// Bytes of the global SDF texture (RG32F, every cascade's slab).
uint64_t cascadeBytes(const GlobalSdfCascadeLayout& layout);

// "64x64x64 voxels of 2.08, 4.17, 8.33, 16.7" (one cascade: "64x29x45 voxels of 0.6").
std::string describeCascades(const GlobalSdfCascadeLayout& layout);

} // namespace lumina::sdf
