#include "gi/sdf/global_sdf_bricks.h"
#include "gi/sdf/scene_sdf_data.h"
#include "tests/sdf/sdf_scene_util.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace lumina::sdf {
namespace {

GlobalSdfSettings grid32() {
    GlobalSdfSettings grid;
    grid.boundsMin = glm::vec3(-8.0f);
    grid.voxelSize = 0.5f;
    grid.dims = {32, 30, 29}; // partial bricks at the far ends of y and z
    grid.maxDistance = 2.0f;
    return grid;
}

gpu::SdfInstanceDesc unitBoxAt(glm::vec3 at) {
    gpu::SdfVolumeDesc volume{};
    volume.volumeMinAndVoxelSize = glm::vec4(-0.5f, -0.5f, -0.5f, 0.1f);
    volume.volumeMaxAndInvVoxelSize = glm::vec4(0.5f, 0.5f, 0.5f, 10.0f);
    return makeInstanceDesc(volume, 0, test::place(at, 0.0f, {0, 1, 0}, glm::vec3(1.0f)), 0, 0, 0.5f);
}

TEST(GlobalSdfBricks, FirstUpdateIsFullThenOnlyMovedRegionsThenNothing) {
    const GlobalSdfSettings grid = grid32();
    const glm::uvec3 bricks = brickDims(grid);
    EXPECT_EQ(bricks, glm::uvec3(8, 8, 8));
    std::vector<gpu::SdfInstanceDesc> instances = {unitBoxAt({-5.2f, -5.2f, -5.2f}), unitBoxAt({5, 5, 5}),
                                                   unitBoxAt({0, 0, 0})};
    GlobalSdfChangeTracker tracker(grid);

    GlobalSdfChangeTracker::Changes first = tracker.update(instances);
    EXPECT_TRUE(first.full);
    EXPECT_EQ(first.dirtyBrickCount, 512u);
    EXPECT_EQ(first.reason, "first compose");
    const ComposeBatch all = makeComposeBatch(grid, instances, first.dirtyBricks);
    EXPECT_EQ(all.voxels, 32u * 30u * 29u);

    GlobalSdfChangeTracker::Changes none = tracker.update(instances);
    EXPECT_FALSE(none.full);
    EXPECT_EQ(none.dirtyBrickCount, 0u);
    EXPECT_EQ(none.reason, "no instance moved");

    instances[0] = unitBoxAt({-5.2f, -5.2f, -4.2f});
    GlobalSdfChangeTracker::Changes moved = tracker.update(instances);
    EXPECT_EQ(moved.changedInstances, 1u);
    // Old box [-5.7, -4.7]^3, new box z in [-4.7, -3.7], grown by maxDistance + one voxel
    // (2.5): x and y reach -2.2, voxel 11, brick 2; z reaches -1.2, voxel 13, brick 3.
    EXPECT_EQ(moved.dirtyBrickCount, 3u * 3u * 4u);
    for (uint32_t z = 0; z < bricks.z; ++z) {
        for (uint32_t y = 0; y < bricks.y; ++y) {
            for (uint32_t x = 0; x < bricks.x; ++x) {
                const bool expected = x <= 2 && y <= 2 && z <= 3;
                EXPECT_EQ(moved.dirtyBricks[(z * bricks.y + y) * bricks.x + x] != 0, expected) << x << y << z;
            }
        }
    }
    tracker.reset();
    EXPECT_TRUE(tracker.update(instances).full);
}

TEST(GlobalSdfBricks, ListsAreAscendingAndHoldEveryInstanceThatCanReachAVoxel) {
    const GlobalSdfSettings grid = grid32();
    std::vector<gpu::SdfInstanceDesc> instances;
    for (int i = 0; i < 20; ++i) {
        instances.push_back(
            unitBoxAt({float(i % 5) * 3.0f - 6.0f, float(i / 5) * 3.0f - 5.0f, float(i % 3) - 1.0f}));
    }
    std::vector<uint8_t> dirty(size_t(8) * 8 * 8, 1);
    const ComposeBatch batch = makeComposeBatch(grid, instances, dirty);
    ASSERT_EQ(batch.bricks.size(), 512u);
    for (const gpu::GlobalSdfBrick& brick : batch.bricks) {
        const glm::uvec4 b = brick.coordAndInstances;
        const glm::uvec3 coord(b.x & 1023u, (b.x >> 10) & 1023u, b.x >> 20);
        const auto first = batch.brickInstances.begin() + b.y;
        std::vector<uint32_t> list(first, first + b.z);
        EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
        // Every voxel centre of the brick within maxDistance of an instance box: listed.
        for (uint32_t i = 0; i < instances.size(); ++i) {
            const bvh::Aabb box = worldBox(instances[i]);
            bool reaches = false;
            for (uint32_t v = 0; v < 64 && !reaches; ++v) {
                const glm::uvec3 voxel = coord * 4u + glm::uvec3(v & 3u, (v >> 2) & 3u, v >> 4);
                if (glm::any(glm::greaterThanEqual(voxel, grid.dims))) {
                    continue;
                }
                const glm::vec3 p = grid.boundsMin + (glm::vec3(voxel) + 0.5f) * grid.voxelSize;
                reaches = glm::length(glm::max(glm::max(box.min - p, glm::vec3(0.0f)), p - box.max)) <
                          grid.maxDistance;
            }
            if (reaches) {
                EXPECT_TRUE(std::binary_search(list.begin(), list.end(), i)) << "instance " << i;
            }
        }
    }
}

} // namespace
} // namespace lumina::sdf
