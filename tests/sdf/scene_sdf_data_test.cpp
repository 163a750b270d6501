#include "gi/sdf/scene_sdf_data.h"
#include "tests/sdf/sdf_scene_util.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <random>

namespace lumina::sdf {
namespace {

class SceneSdfDataTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::random_device random;
        dir_ = std::filesystem::temp_directory_path() / ("lumina_scene_sdf_" + std::to_string(random()));
    }
    void TearDown() override {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    SceneSdfSettings settings() const {
        SceneSdfSettings s;
        s.mesh.resolution = 16;
        s.globalResolution = 32;
        s.cacheDirectory = dir_;
        return s;
    }
    std::filesystem::path dir_;
};

// The 'cache provably skips rebuilds' criterion: a second build of the same scene with the
// same settings builds nothing, and yields the same atlas.
TEST_F(SceneSdfDataTest, SecondBuildLoadsEverythingFromTheCache) {
    const scene::Scene scene = test::makeTestScene();
    const SceneSdfData first = buildSceneSdfData(scene, settings());
    EXPECT_EQ(first.report.meshesBuilt, 4u);
    EXPECT_EQ(first.report.meshesLoaded, 0u);
    EXPECT_GT(first.report.voxelsBuilt, 0u);

    const SceneSdfData second = buildSceneSdfData(scene, settings());
    EXPECT_EQ(second.report.meshesBuilt, 0u);
    EXPECT_EQ(second.report.meshesLoaded, 4u);
    EXPECT_EQ(second.report.voxelsBuilt, 0u);
    EXPECT_EQ(second.report.voxelsLoaded, first.report.voxelsBuilt);
    for (const MeshSdfReport& mesh : second.report.meshes) {
        EXPECT_TRUE(mesh.fromCache) << mesh.name;
    }
    EXPECT_EQ(second.atlas.texelsR16F, first.atlas.texelsR16F);

    // Other settings are another key: built again.
    SceneSdfSettings finer = settings();
    finer.mesh.resolution = 20;
    EXPECT_EQ(buildSceneSdfData(scene, finer).report.meshesBuilt, 4u);
    SceneSdfSettings off = settings();
    off.useCache = false;
    EXPECT_EQ(buildSceneSdfData(scene, off).report.meshesBuilt, 4u);
}

TEST_F(SceneSdfDataTest, InstanceTableAndGridCoverTheScene) {
    scene::Scene scene = test::makeTestScene();
    scene::Mesh empty;
    empty.name = "empty";
    scene.meshes.push_back(empty);
    scene.instances.push_back({4, glm::mat4(1.0f), "empty instance"});
    const SceneSdfData data = buildSceneSdfData(scene, settings());
    ASSERT_EQ(data.instances.size(), 7u); // the empty mesh has no volume, its instance no entry
    EXPECT_EQ(data.meshVolume[4], kNoVolume);
    EXPECT_EQ(data.atlas.volumes.size(), 4u);

    const glm::vec3 gridMax = data.global.boundsMin + glm::vec3(data.global.dims) * data.global.voxelSize;
    EXPECT_EQ(std::max({data.global.dims.x, data.global.dims.y, data.global.dims.z}), 32u);
    EXPECT_FLOAT_EQ(data.global.maxDistance, 8.0f * data.global.voxelSize);
    for (uint32_t i = 0; i < data.instances.size(); ++i) {
        const gpu::SdfInstanceDesc& desc = data.instances[i];
        EXPECT_EQ(desc.ids.z, i);
        EXPECT_EQ(desc.ids.y, scene.instances[i].mesh);
        EXPECT_EQ(desc.ids.x, data.meshVolume[scene.instances[i].mesh]);
        const glm::mat4 m = objectToWorld(desc);
        const glm::mat4 inverse = glm::inverse(scene.instances[i].transform);
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) {
                EXPECT_FLOAT_EQ(m[c][r], scene.instances[i].transform[c][r]);
                EXPECT_FLOAT_EQ(desc.worldToObject[r][c], inverse[c][r]);
            }
        }
        // The world box holds the transformed mesh, and lies inside the grid.
        const bvh::Aabb box = worldBox(desc);
        const scene::Bounds meshWorld = scene::transformBounds(scene.meshes[scene.instances[i].mesh].bounds,
                                                               scene.instances[i].transform);
        EXPECT_TRUE(box.contains({meshWorld.min, meshWorld.max})) << scene.instances[i].name;
        EXPECT_TRUE(bvh::Aabb({data.global.boundsMin, gridMax}).contains(box)) << scene.instances[i].name;
    }
    EXPECT_NEAR(data.instances[1].worldMinAndScale.w, 0.6f, 1e-5f);
    EXPECT_NEAR(data.instances[3].worldMinAndScale.w, 0.6f, 1e-5f); // smallest of 1.5, 0.6, 1
}

TEST_F(SceneSdfDataTest, ScenesOfFewVoxelsPerInstanceGetCascades) {
    // The test scene as it is: its median instance spans many voxels of the fitted grid.
    scene::Scene scene = test::makeTestScene();
    const SceneSdfData compact = buildSceneSdfData(scene, settings());
    EXPECT_EQ(compact.cascades.count, 1u);
    EXPECT_GT(compact.medianInstanceSize, 0.0f);
    // Its instances spread 300 units apart along x: now the fitted grid is far too coarse for
    // them, and the scene gets cascades halving the voxel size, the finest around the camera.
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        scene.instances[i].transform[3].x += 300.0f * float(i);
    }
    scene.camera.position = glm::vec3(900.0f, 0.0f, 0.0f);
    const SceneSdfData spread = buildSceneSdfData(scene, settings());
    EXPECT_NEAR(spread.medianInstanceSize, compact.medianInstanceSize, 1e-3f);
    ASSERT_EQ(spread.cascades.count, 4u);
    EXPECT_EQ(spread.cascades.dims, glm::uvec3(32));
    EXPECT_EQ(spread.global.voxelSize, spread.cascades.finestVoxelSize);
    const bvh::Aabb finest{spread.global.boundsMin,
                           spread.global.boundsMin + glm::vec3(spread.global.dims) * spread.global.voxelSize};
    EXPECT_TRUE(finest.contains({scene.camera.position, scene.camera.position}));
    // A finest voxel size asked for directly decides alone.
    SceneSdfSettings fine = settings();
    fine.globalFinestVoxelSize = 0.05f;
    fine.globalCascades = 2;
    EXPECT_EQ(buildSceneSdfData(test::makeTestScene(), fine).cascades.count, 2u);
    fine.globalFinestVoxelsPerInstance = 0.0f;
    EXPECT_THROW(buildSceneSdfData(test::makeTestScene(), fine), std::invalid_argument);
}

TEST_F(SceneSdfDataTest, AFinerResolutionRefinesTheCascades) {
    // The cascade rules count voxels of a kCascadeRuleResolution grid (docs/gi.md energy 48.): a
    // finer resolution keeps the cascades and shrinks their finest voxel, where counting its own
    // finer voxels had given the city one scene-fitted grid, coarser by the camera than the
    // cascades it replaced.
    scene::Scene scene = test::makeTestScene();
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        scene.instances[i].transform[3].x += 300.0f * float(i);
    }
    SceneSdfSettings s = settings();
    s.globalResolution = kCascadeRuleResolution;
    const SceneSdfData base = buildSceneSdfData(scene, s);
    s.globalResolution = 2 * kCascadeRuleResolution;
    const SceneSdfData finer = buildSceneSdfData(scene, s);
    ASSERT_GT(base.cascades.count, 1u);
    EXPECT_GT(finer.cascades.count, 1u);
    EXPECT_FLOAT_EQ(finer.finestVoxelWanted, 0.5f * base.finestVoxelWanted);
    EXPECT_LT(finer.cascades.finestVoxelSize, base.cascades.finestVoxelSize);
}

TEST_F(SceneSdfDataTest, IdenticalMeshesShareOneVolume) {
    scene::Scene scene = test::makeTestScene();
    scene::Mesh copy = scene.meshes[0];
    copy.name = "sphere copy";
    scene.meshes.push_back(copy);
    scene.instances.push_back(
        {4, test::place({-3.0f, 2.0f, -2.0f}, 0.0f, {0, 1, 0}, glm::vec3(0.4f)), "copy"});
    const SceneSdfData data = buildSceneSdfData(scene, settings());
    EXPECT_EQ(data.report.meshesBuilt, 4u);
    EXPECT_EQ(data.report.meshesShared, 1u);
    EXPECT_EQ(data.atlas.volumes.size(), 4u);
    EXPECT_EQ(data.meshVolume[4], data.meshVolume[0]);
    ASSERT_EQ(data.report.meshes.size(), 5u);
    EXPECT_EQ(data.report.meshes.back().mesh, 4u);
    EXPECT_EQ(data.report.meshes.back().sharedWith, 0u);
    EXPECT_EQ(data.instances.back().ids.x, data.meshVolume[0]);
    EXPECT_EQ(data.instances.back().ids.y, 4u);
}

TEST(MeshTopology, BoundaryEdgesMarkOpenMeshes) {
    const auto open = [](const lumina::test::Mesh& m) { return hasBoundaryEdges(m.positions, m.indices); };
    EXPECT_FALSE(open(lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 2)));
    EXPECT_FALSE(open(lumina::test::makeBox({0, 0, 0}, {1, 2, 3}, 3)));
    EXPECT_TRUE(open(lumina::test::makeBox({0, 0, 0}, {1, 2, 3}, 3, {3})));
    EXPECT_TRUE(open(lumina::test::makeGrid({-1, -1}, {1, 1}, 0.0f, 4)));
    // Split vertices along seams (a box with its own vertices per face) still close.
    lumina::test::Mesh split;
    for (int face = 0; face < 6; ++face) {
        std::vector<int> skip;
        for (int other = 0; other < 6; ++other) {
            if (other != face) {
                skip.push_back(other);
            }
        }
        split.append(lumina::test::makeBox({0, 0, 0}, {1, 1, 1}, 1, skip));
    }
    EXPECT_FALSE(open(split));
}

// Boundary edges make a mesh open (a shell in the global SDF, a thicker near-field threshold)
// only where it is thin: a quad is open, a box missing its bottom face (a block standing on a
// floor, a wall whose hidden faces were left out) is a solid, its SDF negative behind every face.
TEST_F(SceneSdfDataTest, OnlyThinMeshesWithBoundaryEdgesAreOpen) {
    scene::Scene scene;
    scene.meshes.push_back(test::toSceneMesh(lumina::test::makeGrid({-1, -1}, {1, 1}, 0.0f, 4), "quad"));
    scene.meshes.push_back(
        test::toSceneMesh(lumina::test::makeBox({-1.0f, -0.5f, -0.7f}, {1.0f, 0.5f, 0.7f}, 2, {2}), "block"));
    scene.meshes.push_back(test::toSceneMesh(
        lumina::test::makeBox({-1.0f, -0.5f, -0.7f}, {1.0f, 0.5f, 0.7f}, 2), "closed block"));
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        scene.instances.push_back({.mesh = i, .transform = glm::mat4(1.0f), .name = scene.meshes[i].name});
    }
    const SceneSdfData data = buildSceneSdfData(scene, settings());
    const auto open = [&](uint32_t mesh) {
        return (data.atlas.volumes[data.meshVolume[mesh]].dims.w & LUMINA_SDF_VOLUME_OPEN) != 0;
    };
    EXPECT_TRUE(hasBoundaryEdges(scene.meshes[1].positions, scene.meshes[1].indices));
    EXPECT_TRUE(open(0));
    EXPECT_FALSE(open(1));
    EXPECT_FALSE(open(2));
    EXPECT_FALSE(everyFaceBacksOntoInside(data.atlas, data.meshVolume[0], scene.meshes[0].positions,
                                          scene.meshes[0].indices));
}

TEST(GlobalGrid, CubicVoxelsCentredOnTheBox) {
    const GlobalSdfSettings grid = globalGridFor({{0, 0, 0}, {60, 10, 30}}, 64, 2, 4.0f);
    EXPECT_FLOAT_EQ(grid.voxelSize, 1.0f);
    EXPECT_EQ(grid.dims, glm::uvec3(64, 14, 34));
    EXPECT_FLOAT_EQ(grid.maxDistance, 4.0f);
    EXPECT_NEAR(grid.boundsMin.x, -2.0f, 1e-5f);
    EXPECT_NEAR(grid.boundsMin.y, -2.0f, 1e-5f);
    EXPECT_THROW(globalGridFor({{0, 0, 0}, {1, 1, 1}}, 4, 2, 4.0f), std::invalid_argument);
    EXPECT_THROW(globalGridFor({{0, 0, 0}, {1, 1, 1}}, 64, 2, 0.0f), std::invalid_argument);
}

} // namespace
} // namespace lumina::sdf
