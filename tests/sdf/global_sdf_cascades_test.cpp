// Clipmap cascades of the global SDF (gi/sdf/global_sdf_cascades.h): when a scene gets one
// grid (exactly the scene-fitted one) or several, where their windows sit around the camera,
// and which bricks a camera move exposes.
#include "gi/sdf/global_sdf_bricks.h"
#include "gi/sdf/global_sdf_cascades.h"
#include "gi/sdf/mesh_sdf.h"
#include "gi/sdf/scene_sdf_data.h"

#include <gtest/gtest.h>

namespace lumina::sdf {
namespace {

// A city-like box: 1000 x 160 x 1000 with its floor at y = 0.
const bvh::Aabb kCityBox{glm::vec3(-500.0f, 0.0f, -500.0f), glm::vec3(500.0f, 160.0f, 500.0f)};

GlobalSdfCascadeLayout cityLayout() {
    return cascadeLayoutFor(kCityBox, 64, 2, 8.0f, 4, 1.0f);
}

bvh::Aabb windowBox(const GlobalSdfSettings& grid) {
    return {grid.boundsMin, grid.boundsMin + glm::vec3(grid.dims) * grid.voxelSize};
}

TEST(GlobalSdfCascades, ASmallSceneGetsExactlyTheSceneFittedGrid) {
    const bvh::Aabb room{glm::vec3(-1.0f, 0.0f, -1.2f), glm::vec3(1.0f, 2.0f, 1.0f)};
    const GlobalSdfSettings fitted = globalGridFor(room, 64, 2, 8.0f);
    const GlobalSdfCascadeLayout layout = cascadeLayoutFor(room, 64, 2, 8.0f, 4, 1.0f);
    ASSERT_EQ(layout.count, 1u);
    EXPECT_FALSE(layout.scrolls());
    for (const glm::vec3 camera : {glm::vec3(0.0f), glm::vec3(100.0f, -3.0f, 7.0f)}) {
        const glm::ivec3 window = cascadeWindowFor(layout, 0, camera);
        EXPECT_EQ(window, glm::ivec3(0));
        const GlobalSdfSettings grid = cascadeGrid(layout, 0, window);
        // Bit for bit: the stored goldens of the small scenes depend on it.
        EXPECT_EQ(grid.boundsMin, fitted.boundsMin);
        EXPECT_EQ(grid.voxelSize, fitted.voxelSize);
        EXPECT_EQ(grid.dims, fitted.dims);
        EXPECT_EQ(grid.maxDistance, fitted.maxDistance);
        EXPECT_EQ(grid.openShellExtra, 0.0f);
    }
    // One cascade asked for: the fitted grid even for a large scene.
    EXPECT_EQ(cascadeLayoutFor(kCityBox, 64, 2, 8.0f, 1, 1.0f).count, 1u);
}

TEST(GlobalSdfCascades, ALargeSceneGetsCascadesHalvingTheVoxelSize) {
    const GlobalSdfCascadeLayout layout = cityLayout();
    const GlobalSdfSettings fitted = globalGridFor(kCityBox, 64, 2, 8.0f);
    ASSERT_EQ(layout.count, 4u); // 16.7 -> 8.3 -> 4.2 -> 2.1: capped at 4 above the 1.0 asked for
    EXPECT_EQ(layout.dims, glm::uvec3(64));
    EXPECT_EQ(layout.voxelSize(3), fitted.voxelSize);
    for (uint32_t c = 1; c < layout.count; ++c) {
        EXPECT_EQ(layout.voxelSize(c), 2.0f * layout.voxelSize(c - 1));
    }
    EXPECT_GT(layout.finestVoxelSize, 1.0f);
    EXPECT_EQ(cascadeBytes(layout), 4ull * 64 * 64 * 64 * 8);
    // Enough cascades allowed: the finest reaches the size asked for.
    EXPECT_LE(cascadeLayoutFor(kCityBox, 64, 2, 8.0f, 6, 1.0f).finestVoxelSize, 1.0f);
    EXPECT_THROW(cascadeLayoutFor(kCityBox, 64, 2, 8.0f, 0, 1.0f), std::invalid_argument);
    EXPECT_THROW(cascadeLayoutFor(kCityBox, 64, 2, 8.0f, LUMINA_SDF_MAX_CASCADES + 1, 1.0f),
                 std::invalid_argument);
    EXPECT_THROW(cascadeLayoutFor(kCityBox, 64, 2, 8.0f, 4, 0.0f), std::invalid_argument);
}

TEST(GlobalSdfCascades, WindowsSurroundTheCameraInsideTheScene) {
    const GlobalSdfCascadeLayout layout = cityLayout();
    const glm::vec3 camera(37.0f, 1.8f, -120.0f); // street level, away from the edges
    for (uint32_t c = 0; c < layout.count; ++c) {
        const glm::ivec3 window = cascadeWindowFor(layout, c, camera);
        EXPECT_EQ(window % int32_t(kSdfBrickSize), glm::ivec3(0)) << "cascade " << c;
        const GlobalSdfSettings grid = cascadeGrid(layout, c, window);
        const bvh::Aabb box = windowBox(grid);
        const float side = 64.0f * grid.voxelSize;
        // Horizontally the camera is within two bricks of the window's centre (snapping) or the
        // window is held inside the scene; the 160 m tall scene fits the three coarser windows,
        // which centre on it vertically.
        for (int a : {0, 2}) {
            if (side < kCityBox.size()[a]) {
                const float offCentre = std::abs(camera[a] - box.centre()[a]);
                EXPECT_LE(offCentre, 2.0f * float(kSdfBrickSize) * grid.voxelSize)
                    << "cascade " << c << " axis " << a;
            }
        }
        EXPECT_TRUE(box.contains({camera, camera})) << "cascade " << c;
        if (side >= layout.coverBox.size().y) {
            EXPECT_NEAR(box.centre().y, layout.coverBox.centre().y,
                        2.0f * float(kSdfBrickSize) * grid.voxelSize);
        }
    }
    // The coarsest covers the whole scene, wherever the camera is.
    for (const glm::vec3 anywhere :
         {camera, glm::vec3(480.0f, 150.0f, 480.0f), glm::vec3(-499.0f, 0.0f, 0.0f)}) {
        const uint32_t coarsest = layout.count - 1;
        const bvh::Aabb box =
            windowBox(cascadeGrid(layout, coarsest, cascadeWindowFor(layout, coarsest, anywhere)));
        EXPECT_TRUE(box.contains(kCityBox));
    }
    // At the scene's edge the finest window stays inside the scene's (padded) box rather than
    // spending half its voxels outside.
    const glm::vec3 corner(499.0f, 1.8f, -499.0f);
    const GlobalSdfSettings edge = cascadeGrid(layout, 0, cascadeWindowFor(layout, 0, corner));
    const bvh::Aabb edgeBox = windowBox(edge);
    EXPECT_TRUE(edgeBox.contains({corner, corner}));
    EXPECT_LE(edgeBox.max.x, layout.coverBox.max.x + 2.0f * float(kSdfBrickSize) * edge.voxelSize);
    EXPECT_GE(edgeBox.min.z, layout.coverBox.min.z - 2.0f * float(kSdfBrickSize) * edge.voxelSize);
}

TEST(GlobalSdfCascades, AMoveExposesOnlyTheBricksThatEnterTheWindow) {
    const GlobalSdfCascadeLayout layout = cityLayout();
    const glm::vec3 camera(37.0f, 1.8f, -120.0f);
    const float finest = layout.voxelSize(0);
    // Eight finest voxels along +x: two brick columns of the finest window enter, 16 x 16 each.
    const glm::vec3 moved = camera + glm::vec3(8.0f * finest, 0.0f, 0.0f);
    const glm::ivec3 from = cascadeWindowFor(layout, 0, camera);
    const glm::ivec3 to = cascadeWindowFor(layout, 0, moved);
    ASSERT_EQ(to - from, glm::ivec3(8, 0, 0));
    uint32_t count = 0;
    const std::vector<uint8_t> exposed = exposedBricks(layout, from, to, &count);
    ASSERT_EQ(exposed.size(), 16u * 16u * 16u);
    EXPECT_EQ(count, 2u * 16u * 16u);
    for (uint32_t z = 0; z < 16; ++z) {
        for (uint32_t y = 0; y < 16; ++y) {
            for (uint32_t x = 0; x < 16; ++x) {
                EXPECT_EQ(exposed[(z * 16 + y) * 16 + x] != 0, x >= 14) << x << " " << y << " " << z;
            }
        }
    }
    // The coarsest cascade holds the whole scene: it does not move.
    EXPECT_EQ(cascadeWindowFor(layout, 3, camera), cascadeWindowFor(layout, 3, moved));
    // No move, nothing exposed; a jump past the window's width, everything.
    exposedBricks(layout, to, to, &count);
    EXPECT_EQ(count, 0u);
    exposedBricks(layout, from, from + glm::ivec3(0, 0, -64), &count);
    EXPECT_EQ(count, 16u * 16u * 16u);
}

TEST(GlobalSdfCascades, ALatticeVoxelKeepsItsTexelWhenTheWindowMoves) {
    const GlobalSdfCascadeLayout layout = cityLayout();
    const glm::ivec3 from(-40, -8, 12), to(-28, -8, 4);
    for (uint32_t i = 0; i < 64; ++i) {
        // Lattice voxel from + (i, 5, 40): inside both windows when 12 <= i.
        const glm::ivec3 lattice = from + glm::ivec3(int32_t(i), 5, 40);
        const glm::uvec3 before = cascadeTexel(layout, from, glm::uvec3(lattice - from));
        EXPECT_TRUE(glm::all(glm::lessThan(before, layout.dims)));
        if (i >= 12) {
            EXPECT_EQ(cascadeTexel(layout, to, glm::uvec3(lattice - to)), before) << i;
        }
    }
}

TEST(GlobalSdfCascades, ChangeTrackingFollowsAMovedGrid) {
    // An instance that moves inside a scrolled window marks bricks of that window.
    const GlobalSdfCascadeLayout layout = cityLayout();
    gpu::SdfVolumeDesc volume{};
    volume.volumeMinAndVoxelSize = glm::vec4(-5.0f, 0.0f, -5.0f, 0.5f);
    volume.volumeMaxAndInvVoxelSize = glm::vec4(5.0f, 20.0f, 5.0f, 2.0f);
    const auto at = [&](glm::vec3 p) {
        glm::mat4 m(1.0f);
        m[3] = glm::vec4(p, 1.0f);
        return makeInstanceDesc(volume, 0, m, 0, 0, layout.finestVoxelSize);
    };
    std::vector<gpu::SdfInstanceDesc> instances = {at({40.0f, 0.0f, -120.0f})};
    const glm::ivec3 first = cascadeWindowFor(layout, 0, {37.0f, 1.8f, -120.0f});
    GlobalSdfChangeTracker tracker(cascadeGrid(layout, 0, first));
    EXPECT_TRUE(tracker.update(instances).full);
    const glm::ivec3 second = cascadeWindowFor(layout, 0, {57.0f, 1.8f, -120.0f});
    ASSERT_NE(second, first);
    tracker.setGrid(cascadeGrid(layout, 0, second));
    EXPECT_EQ(tracker.update(instances).dirtyBrickCount, 0u); // the move alone: exposedBricks' job
    instances[0] = at({60.0f, 0.0f, -120.0f});
    const GlobalSdfChangeTracker::Changes changes = tracker.update(instances);
    EXPECT_EQ(changes.changedInstances, 1u);
    const GlobalSdfSettings grid = cascadeGrid(layout, 0, second);
    const BrickRange oldRange =
        bricksTouched(grid, worldBox(at({40.0f, 0.0f, -120.0f})), influenceMargin(grid, instances[0]));
    const BrickRange newRange =
        bricksTouched(grid, worldBox(instances[0]), influenceMargin(grid, instances[0]));
    ASSERT_FALSE(oldRange.empty);
    ASSERT_FALSE(newRange.empty);
    EXPECT_GT(changes.dirtyBrickCount, 0u);
    const glm::uvec3 bricks = brickDims(grid);
    const size_t newCorner = (size_t(newRange.hi.z) * bricks.y + newRange.hi.y) * bricks.x + newRange.hi.x;
    const size_t oldCorner = (size_t(oldRange.lo.z) * bricks.y + oldRange.lo.y) * bricks.x + oldRange.lo.x;
    EXPECT_EQ(changes.dirtyBricks[newCorner], 1u);
    EXPECT_EQ(changes.dirtyBricks[oldCorner], 1u);
}

} // namespace
} // namespace lumina::sdf
