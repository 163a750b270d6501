#include "gi/sdf/global_sdf.h"
#include "tests/bvh/test_meshes.h"
#include "tests/sdf/sdf_test_util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lumina::sdf {
namespace {

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
    GlobalSdfSettings grid;
    grid.boundsMin = {-4.0f, -4.0f, -4.0f};
    grid.voxelSize = 0.25f;
    grid.dims = {32, 32, 32};
    grid.maxDistance = 3.0f;
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
