#pragma once
// Incremental composition of the global SDF: the grid is cut into bricks of
// LUMINA_SDF_BRICK_SIZE^3 voxels, and only bricks an instance's move can change are
// recomposed.
//
// Why this is exact: a voxel takes an instance into account only when the voxel centre
// lies within maxDistance + shell (SdfInstanceDesc::worldMax.w, 0 unless open) of the
// instance's world box (composeGlobalSdf skips it otherwise, and the GPU kernel does the
// same). A brick's instance list holds every instance whose box, grown by the margin
// maxDistance + shell + one voxel (slack for rounding), touches the brick, in ascending order; so a brick
// that neither the old nor the new grown box of a moved instance touches has the same list and the same
// values before and after, and recomposing only the touched bricks gives exactly what recomposing everything
// gives.
#include "gi/bvh/bvh.h"
#include "gi/sdf/global_sdf.h"
#include "shaders/common/sdf_scene_shared.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lumina::sdf {

inline constexpr uint32_t kSdfBrickSize = LUMINA_SDF_BRICK_SIZE;

glm::uvec3 brickDims(const GlobalSdfSettings& grid);
// Distance from an instance's box within which it can change a voxel (see above).
float influenceMargin(const GlobalSdfSettings& grid, const gpu::SdfInstanceDesc& instance);

struct BrickRange {
    glm::uvec3 lo{0}, hi{0}; // inclusive
    bool empty = true;
};
// The bricks that `box` grown by `margin` touches (empty when it misses the grid).
BrickRange bricksTouched(const GlobalSdfSettings& grid, const bvh::Aabb& box, float margin);

struct ComposeBatch {
    std::vector<gpu::GlobalSdfBrick> bricks;
    std::vector<uint32_t> brickInstances; // the bricks' instance lists, concatenated
    uint64_t voxels = 0;                  // grid voxels the bricks cover
};

// The bricks flagged in `dirty` (one flag per brick, x fastest), each with its instance list.
ComposeBatch makeComposeBatch(const GlobalSdfSettings& grid, std::span<const gpu::SdfInstanceDesc> instances,
                              const std::vector<uint8_t>& dirty);

// Remembers each instance's transform (as a hash) and world box between updates.
class GlobalSdfChangeTracker {
public:
    struct Changes {
        std::vector<uint8_t> dirtyBricks; // one flag per brick, x fastest
        uint32_t dirtyBrickCount = 0;
        uint32_t changedInstances = 0;
        bool full = false;  // everything recomposed: first update, reset, or the table changed size
        std::string reason; // why nothing is recomposed, or what is
    };

    explicit GlobalSdfChangeTracker(const GlobalSdfSettings& grid) : grid_(grid) {}

    Changes update(std::span<const gpu::SdfInstanceDesc> instances);
    // The grid moved (a scrolled cascade's window): later updates mark bricks of the new one.
    // Instances' remembered boxes stay in world space, so they still name what a move changes.
    void setGrid(const GlobalSdfSettings& grid) { grid_ = grid; }
    const GlobalSdfSettings& grid() const { return grid_; }
    // The next update recomposes everything.
    void reset() { hashes_.clear(); }

private:
    GlobalSdfSettings grid_;
    std::vector<uint64_t> hashes_;
    std::vector<bvh::Aabb> boxes_;
    std::vector<float> margins_;
};

// FNV-1a over the bytes that place an instance (transform rows and volume).
uint64_t instanceHash(const gpu::SdfInstanceDesc& instance);

} // namespace lumina::sdf
