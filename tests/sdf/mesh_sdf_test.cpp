#include "gi/bvh/bvh_query.h"
#include "gi/sdf/mesh_sdf.h"
#include "tests/bvh/test_meshes.h"
#include "tests/sdf/sdf_test_util.h"

#include <cstring>
#include <functional>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace lumina::sdf {
namespace {

SdfSettings small(uint32_t resolution = 32) {
    SdfSettings settings;
    settings.resolution = resolution;
    return settings;
}

TEST(MeshSdf, VolumeCoversTheMeshWithPadding) {
    const lumina::test::Mesh box = lumina::test::makeBox({-1.0f, -0.5f, -0.25f}, {3.0f, 0.5f, 0.25f}, 1);
    const MeshSdf sdf = buildMeshSdf(box.positions, box.indices, small(32));
    EXPECT_EQ(sdf.dims.x, 32u); // longest axis: the resolution, padding included
    EXPECT_FLOAT_EQ(sdf.voxelSize, 4.0f / 28.0f);
    EXPECT_EQ(sdf.dims.y, 7u + 4u);
    EXPECT_EQ(sdf.dims.z, 4u + 4u);
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(sdf.volumeMin[a] + 2.0f * sdf.voxelSize, sdf.meshBounds.min[a] + 1e-5f);
        EXPECT_GE(sdf.volumeMax()[a] - 2.0f * sdf.voxelSize, sdf.meshBounds.max[a] - 1e-5f);
    }
    EXPECT_EQ(sdf.distances.size(), size_t(32) * 11 * 8);
    EXPECT_EQ(sdf.stats.triangles, 12u);
    EXPECT_GT(sdf.stats.signRays, 0u);
}

// At voxel centres the magnitude is the exact distance to the triangles (a box mesh's
// distance is the box's analytic distance), and between them trilinear filtering of a
// 1-Lipschitz function is off by at most half a voxel diagonal.
TEST(MeshSdf, BoxMatchesAnalyticDistance) {
    const glm::vec3 lo(-1.0f, -0.6f, -0.8f), hi(1.2f, 0.9f, 0.4f);
    const lumina::test::Mesh box = lumina::test::makeBox(lo, hi, 3);
    const MeshSdf sdf = buildMeshSdf(box.positions, box.indices, small(32));
    for (uint32_t z = 0; z < sdf.dims.z; ++z) {
        for (uint32_t y = 0; y < sdf.dims.y; ++y) {
            for (uint32_t x = 0; x < sdf.dims.x; ++x) {
                const float exact = test::boxDistance(sdf.voxelCentre(x, y, z), lo, hi);
                ASSERT_NEAR(sdf.at(x, y, z), exact, 1e-5f) << x << "," << y << "," << z;
            }
        }
    }
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float tolerance = 0.5f * std::sqrt(3.0f) * sdf.voxelSize;
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 p =
            sdf.volumeMin + glm::vec3(u(rng), u(rng), u(rng)) * (sdf.volumeMax() - sdf.volumeMin);
        EXPECT_NEAR(test::sampleGrid(sdf, p), test::boxDistance(p, lo, hi), tolerance);
    }
}

TEST(MeshSdf, SphereMatchesAnalyticDistance) {
    const glm::vec3 centre(0.2f, -0.1f, 0.3f);
    const float radius = 1.0f;
    const lumina::test::Mesh sphere = lumina::test::makeIcosphere(centre, radius, 4);
    const MeshSdf sdf = buildMeshSdf(sphere.positions, sphere.indices, small(32));
    // The mesh lies inside the sphere by at most its sagitta (edge ~0.077: ~1e-3).
    const float meshError = 2e-3f;
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float tolerance = 0.5f * std::sqrt(3.0f) * sdf.voxelSize + meshError;
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 p =
            sdf.volumeMin + glm::vec3(u(rng), u(rng), u(rng)) * (sdf.volumeMax() - sdf.volumeMin);
        EXPECT_NEAR(test::sampleGrid(sdf, p), test::sphereDistance(p, centre, radius), tolerance);
    }
}

// Sign by ray voting on closed meshes: every voxel centre not on the surface gets the side
// it is on (the requirement is 99.9%; watertight rays make it exact here).
TEST(MeshSdf, SignsAreRightOnClosedMeshes) {
    const glm::vec3 lo(-1.0f, -0.3f, -0.7f), hi(0.8f, 0.6f, 0.9f);
    const lumina::test::Mesh box = lumina::test::makeBox(lo, hi, 4);
    const lumina::test::Mesh sphere = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 3);
    struct Case {
        const lumina::test::Mesh* mesh;
        std::function<float(const glm::vec3&)> exact;
        float surfaceTolerance; // how far the mesh may be from the analytic surface
    };
    const Case cases[] = {
        {&box, [&](const glm::vec3& p) { return test::boxDistance(p, lo, hi); }, 1e-5f},
        {&sphere,
         [](const glm::vec3& p) {
             return test::sphereDistance(p, {0, 0, 0}, 1.0f);
         },
         5e-3f},
    };
    for (const Case& c : cases) {
        const MeshSdf sdf = buildMeshSdf(c.mesh->positions, c.mesh->indices, small(32));
        size_t checked = 0, wrong = 0;
        for (uint32_t z = 0; z < sdf.dims.z; ++z) {
            for (uint32_t y = 0; y < sdf.dims.y; ++y) {
                for (uint32_t x = 0; x < sdf.dims.x; ++x) {
                    const float exact = c.exact(sdf.voxelCentre(x, y, z));
                    if (std::abs(exact) <= c.surfaceTolerance) {
                        continue;
                    }
                    ++checked;
                    wrong += (exact < 0.0f) != (sdf.at(x, y, z) < 0.0f);
                }
            }
        }
        EXPECT_GT(checked, 10000u);
        EXPECT_LE(double(wrong), 0.001 * double(checked)) << wrong << " of " << checked;
        EXPECT_EQ(wrong, 0u);
    }
}

// Open meshes (documented in mesh_sdf.h): a lone quad is a two-sided surface, positive
// everywhere; a box without its lid is negative deep inside, positive outside its walls and
// above the opening.
TEST(MeshSdf, OpenMeshesGetSaneSigns) {
    const std::vector<glm::vec3> quad = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    const std::vector<uint32_t> quadIndices = {0, 2, 1, 0, 3, 2};
    const MeshSdf quadSdf = buildMeshSdf(quad, quadIndices, small(32));
    for (uint32_t z = 0; z < quadSdf.dims.z; ++z) {
        for (uint32_t y = 0; y < quadSdf.dims.y; ++y) {
            for (uint32_t x = 0; x < quadSdf.dims.x; ++x) {
                const glm::vec3 p = quadSdf.voxelCentre(x, y, z);
                const float exact = test::boxDistance(p, {-1, 0, -1}, {1, 0, 1});
                ASSERT_NEAR(quadSdf.at(x, y, z), exact, 1e-5f) << x << "," << y << "," << z;
            }
        }
    }

    // Box [-1,1]^3 without its +y face.
    const lumina::test::Mesh openBox = lumina::test::makeBox({-1, -1, -1}, {1, 1, 1}, 2, {3});
    const MeshSdf sdf = buildMeshSdf(openBox.positions, openBox.indices, small(32));
    size_t deepInside = 0, deepInsideNegative = 0, outside = 0, outsideNegative = 0;
    for (uint32_t z = 0; z < sdf.dims.z; ++z) {
        for (uint32_t y = 0; y < sdf.dims.y; ++y) {
            for (uint32_t x = 0; x < sdf.dims.x; ++x) {
                const glm::vec3 p = sdf.voxelCentre(x, y, z);
                const float value = sdf.at(x, y, z);
                ASSERT_TRUE(std::isfinite(value));
                const float box = test::boxDistance(p, {-1, -1, -1}, {1, 1, 1});
                if (box < -0.1f && p.y < 0.2f) { // the lower part of the inside
                    ++deepInside;
                    deepInsideNegative += value < 0.0f;
                } else if (box > 0.05f) { // outside the closed box, including above the opening
                    ++outside;
                    outsideNegative += value < 0.0f;
                }
            }
        }
    }
    EXPECT_GT(deepInside, 1000u);
    EXPECT_EQ(deepInsideNegative, deepInside);
    EXPECT_EQ(outsideNegative, 0u) << "of " << outside;
}

TEST(MeshSdf, ThreadCountDoesNotChangeTheResult) {
    const lumina::test::Mesh sphere = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 2);
    SdfSettings one = small(24), two = small(24);
    one.threads = 1;
    two.threads = 3;
    const MeshSdf a = buildMeshSdf(sphere.positions, sphere.indices, one);
    const MeshSdf b = buildMeshSdf(sphere.positions, sphere.indices, two);
    ASSERT_EQ(a.distances.size(), b.distances.size());
    EXPECT_EQ(0, std::memcmp(a.distances.data(), b.distances.data(), a.distances.size() * sizeof(float)));
}

TEST(MeshSdf, ABatchBuildsWhatEachMeshBuildsAlone) {
    // Closed, open and lid-less meshes of different sizes, so that slices of several meshes
    // interleave on the threads.
    const lumina::test::Mesh sphere = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 2);
    const lumina::test::Mesh openBox =
        lumina::test::makeBox({-0.8f, -0.8f, -0.8f}, {0.8f, 0.8f, 0.8f}, 2, {3});
    const lumina::test::Mesh slab = lumina::test::makeBox({-4.0f, -0.3f, -3.5f}, {4.0f, 0.3f, 3.5f}, 4);
    const std::vector<MeshSdfInput> inputs = {{sphere.positions, sphere.indices},
                                              {openBox.positions, openBox.indices},
                                              {slab.positions, slab.indices}};
    SdfSettings alone = small(24), batch = small(24);
    alone.threads = 1;
    batch.threads = 3;
    const std::vector<MeshSdf> built = buildMeshSdfs(inputs, batch);
    ASSERT_EQ(built.size(), inputs.size());
    for (size_t m = 0; m < inputs.size(); ++m) {
        const MeshSdf single = buildMeshSdf(inputs[m].positions, inputs[m].indices, alone);
        EXPECT_EQ(built[m].dims, single.dims);
        EXPECT_EQ(built[m].volumeMin, single.volumeMin);
        ASSERT_EQ(built[m].distances.size(), single.distances.size());
        EXPECT_EQ(0, std::memcmp(built[m].distances.data(), single.distances.data(),
                                 single.distances.size() * sizeof(float)))
            << "mesh " << m;
        EXPECT_GT(built[m].stats.signRays, 0u);
    }
    const std::vector<MeshSdfInput> withEmpty = {inputs[0], {sphere.positions, {}}};
    EXPECT_THROW(buildMeshSdfs(withEmpty, batch), std::invalid_argument);
    EXPECT_TRUE(buildMeshSdfs({}, batch).empty());
}

TEST(MeshSdf, RejectsBadInput) {
    const lumina::test::Mesh box = lumina::test::makeBox({0, 0, 0}, {1, 1, 1});
    SdfSettings settings;
    settings.resolution = 8;
    settings.padding = 4;
    EXPECT_THROW(buildMeshSdf(box.positions, box.indices, settings), std::invalid_argument);
    settings = {};
    settings.signRays = 0;
    EXPECT_THROW(buildMeshSdf(box.positions, box.indices, settings), std::invalid_argument);
    settings = {};
    settings.signRays = 33;
    EXPECT_THROW(buildMeshSdf(box.positions, box.indices, settings), std::invalid_argument);
    settings = {};
    settings.insideFraction = 1.0f;
    EXPECT_THROW(buildMeshSdf(box.positions, box.indices, settings), std::invalid_argument);
    EXPECT_THROW(buildMeshSdf(box.positions, {}, {}), std::invalid_argument);
}

TEST(MeshSdf, SignRayDirectionsAreUnitAndSpread) {
    const std::vector<glm::vec3> dirs = signRayDirections(32);
    ASSERT_EQ(dirs.size(), 32u);
    glm::vec3 mean(0.0f);
    for (const glm::vec3& d : dirs) {
        EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
        EXPECT_NE(d.x, 0.0f);
        EXPECT_NE(d.y, 0.0f);
        mean += d / 32.0f;
    }
    EXPECT_LT(glm::length(mean), 0.05f);
    // Antipodal pairs: any half-space holds exactly half of them.
    std::mt19937 rng(3);
    for (int i = 0; i < 100; ++i) {
        const glm::vec3 axis = lumina::test::randomUnitVector(rng);
        int positive = 0;
        for (const glm::vec3& d : dirs) {
            positive += glm::dot(d, axis) > 0.0f;
        }
        EXPECT_EQ(positive, 16);
    }
}

} // namespace
} // namespace lumina::sdf
