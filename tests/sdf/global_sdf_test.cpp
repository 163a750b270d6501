#include "gi/sdf/global_sdf.h"
#include "tests/bvh/test_meshes.h"
#include "tests/sdf/sdf_test_util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lumina::sdf {
namespace {

// n^3 voxels of `voxel` from (corner, corner, corner), truncated at maxDistance.
GlobalSdfSettings cubicGrid(float corner, float voxel, uint32_t n, float maxDistance) {
    GlobalSdfSettings grid;
    grid.boundsMin = glm::vec3(corner);
    grid.voxelSize = voxel;
    grid.dims = glm::uvec3(n);
    grid.maxDistance = maxDistance;
    return grid;
}

TEST(GlobalSdf, MatchesAnalyticSpheresAndNamesTheNearest) {
    // One unit-sphere SDF, instanced three times with translation, rotation and uniform scale.
    const lumina::test::Mesh mesh = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 3);
    SdfSettings settings;
    settings.resolution = 32;
    const MeshSdf sdf = buildMeshSdf(mesh.positions, mesh.indices, settings);
    const SdfAtlas atlas = packSdfs(std::span<const MeshSdf>(&sdf, 1));

    struct Sphere {
        glm::vec3 centre;
        float radius;
    };
    const Sphere spheres[] = {
        {{-2.0f, 0.0f, 0.0f}, 1.0f}, {{1.5f, 1.0f, 0.5f}, 0.5f}, {{1.0f, -1.5f, -1.0f}, 1.5f}};
    std::vector<SdfInstance> instances;
    for (const Sphere& s : spheres) {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), s.centre);
        m = glm::rotate(m, 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
        m = glm::scale(m, glm::vec3(s.radius));
        instances.push_back({m, 0});
    }
    const GlobalSdfSettings grid = cubicGrid(-4.0f, 0.25f, 32, 3.0f);
    const GlobalSdf global = composeGlobalSdf(atlas, instances, grid);
    ASSERT_EQ(global.distances.size(), 32u * 32u * 32u);

    // Near a sphere the mesh SDF is off by at most half its voxel diagonal (scaled) plus the
    // icosphere's sagitta; far outside the volumes it is a lower bound.
    const float meshTolerance = 0.5f * std::sqrt(3.0f) * sdf.voxelSize + 5e-3f;
    uint32_t namedRight = 0, named = 0;
    for (uint32_t z = 0; z < 32; ++z) {
        for (uint32_t y = 0; y < 32; ++y) {
            for (uint32_t x = 0; x < 32; ++x) {
                const glm::vec3 p = global.voxelCentre(x, y, z);
                float best = 1e30f, second = 1e30f;
                uint32_t nearest = kNoInstance;
                for (uint32_t i = 0; i < 3; ++i) {
                    const float d = test::sphereDistance(p, spheres[i].centre, spheres[i].radius);
                    if (d < best) {
                        second = best;
                        best = d;
                        nearest = i;
                    } else {
                        second = std::min(second, d);
                    }
                }
                const size_t index = global.voxelIndex(x, y, z);
                const float value = global.distances[index];
                const float tolerance = meshTolerance * 1.5f; // largest instance scale
                EXPECT_LE(value, std::min(best, grid.maxDistance) + tolerance)
                    << p.x << "," << p.y << "," << p.z;
                // Inside the nearest sphere's volume (a box of half-size 1.2 r: the sphere of
                // radius 1.2 r fits in it) the value is that sphere's distance; beyond the
                // volumes it is a lower bound, and the instance named there may be another.
                const bool inNearestVolume =
                    glm::length(p - spheres[nearest].centre) < 1.15f * spheres[nearest].radius;
                if (inNearestVolume) {
                    EXPECT_NEAR(value, best, tolerance);
                }
                EXPECT_GE(value, -grid.maxDistance);
                if (inNearestVolume && second - best > 2.0f * tolerance) {
                    ++named;
                    namedRight += global.instances[index] == nearest;
                }
                if (value >= grid.maxDistance) {
                    EXPECT_EQ(global.instances[index], kNoInstance);
                }
            }
        }
    }
    EXPECT_GT(named, 1000u);
    EXPECT_EQ(namedRight, named);
}

// A slab of `thickness` across x (centred at x = centre, 2 x 2 wide in y and z) composed into a
// grid of 0.25 voxels whose centres lie at x = +-0.125, +-0.375, ...: the column (y, z) of voxels
// through the slab's middle, and the mesh SDF's own value at each (no shell).
struct SlabColumn {
    std::vector<float> values, unshelled; // along x, from x = -0.875 to 0.875
};

SlabColumn composeSlab(float centre, float thickness) {
    const lumina::test::Mesh mesh = lumina::test::makeBox({centre - 0.5f * thickness, -1.0f, -1.0f},
                                                          {centre + 0.5f * thickness, 1.0f, 1.0f}, 2);
    SdfSettings settings;
    settings.resolution = 64;
    const MeshSdf sdf = buildMeshSdf(mesh.positions, mesh.indices, settings);
    const SdfAtlas atlas = packSdfs(std::span<const MeshSdf>(&sdf, 1));
    EXPECT_EQ(atlas.volumes[0].dims.w & LUMINA_SDF_VOLUME_OPEN, 0u) << "a closed box is a solid";
    const std::vector<SdfInstance> instances = {{glm::mat4(1.0f), 0}};
    const GlobalSdf global = composeGlobalSdf(atlas, instances, cubicGrid(-1.0f, 0.25f, 8, 2.0f));
    SlabColumn column;
    for (uint32_t x = 0; x < 8; ++x) {
        column.values.push_back(global.distances[global.voxelIndex(x, 4, 3)]);
        column.unshelled.push_back(sampleSdf(atlas, 0, global.voxelCentre(x, 4, 3)));
    }
    return column;
}

TEST(GlobalSdf, ASolidThinnerThanAVoxelIsOneVoxelThickToTheGrid) {
    // 4 cm thick, between the voxel centres at x = 0.125 (0.095 from its middle) and -0.125: its
    // own field is positive at both, so a far-field ray would cross it.
    const SlabColumn thin = composeSlab(0.03f, 0.04f);
    ASSERT_GT(thin.unshelled[4], 0.0f);
    ASSERT_GT(thin.unshelled[3], 0.0f);
    EXPECT_LT(thin.values[4], 0.0f) << "the voxel nearest the slab must be inside its shell";
    // The shell makes up what the slab lacks of half a voxel's depth (0.125 less the slab's
    // sampled depth, at most its 0.02), in full within two voxels of it.
    for (uint32_t x = 2; x < 6; ++x) {
        const float shell = thin.unshelled[x] - thin.values[x];
        EXPECT_GE(shell, 0.1f) << "x = " << x;
        EXPECT_LE(shell, 0.125f + 1e-5f) << "x = " << x;
    }
    // The voxel 0.9 away lies where the shell fades (3 to 4 voxels): it gets less of it.
    EXPECT_LT(thin.unshelled[0] - thin.values[0], thin.unshelled[2] - thin.values[2] - 0.01f);
}

TEST(GlobalSdf, ASolidAtLeastAVoxelThickKeepsItsDistance) {
    // 0.3 thick, centred at 0: its half thickness (0.15) exceeds half a voxel (0.125), so every
    // voxel reads the mesh SDF's own value.
    const SlabColumn thick = composeSlab(0.0f, 0.3f);
    for (uint32_t x = 0; x < 8; ++x) {
        EXPECT_EQ(thick.values[x], thick.unshelled[x]) << "x = " << x;
    }
}

TEST(GlobalSdf, RejectsBadInput) {
    const SdfAtlas atlas;
    const std::vector<SdfInstance> instances = {{glm::mat4(1.0f), 0}};
    GlobalSdfSettings grid;
    EXPECT_THROW(composeGlobalSdf(atlas, instances, grid), std::invalid_argument);
    grid.voxelSize = 0.0f;
    EXPECT_THROW(composeGlobalSdf(atlas, {}, grid), std::invalid_argument);
    grid.voxelSize = 1.0f;
    const GlobalSdf empty = composeGlobalSdf(atlas, {}, grid);
    EXPECT_EQ(empty.instances[0], kNoInstance);
}

} // namespace
} // namespace lumina::sdf
