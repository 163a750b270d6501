// The small built-in scenes are files under scenes/, written by code in
// gi/scene/generators. This test regenerates them in memory and checks that the committed
// files still say the same thing. To rewrite the files after changing a generator:
//
//   LUMINA_UPDATE_SCENES=1 LUMINA_SOURCE_DIR=$PWD build/tests/scene/scene_tests
//   --gtest_filter='BuiltinFiles.*'
#include "gi/scene/builtin_scenes.h"
#include "gi/scene/gltf_writer.h"
#include "gi/scene/scene_loader.h"
#include "tests/scene/test_files.h"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance, const std::string& what) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a[i], b[i], tolerance * std::max(1.0f, std::abs(b[i]))) << what << " component " << i;
    }
}

void expectSameScene(const Scene& actual, const Scene& expected) {
    constexpr float kTolerance = 1e-5f;
    ASSERT_EQ(actual.meshes.size(), expected.meshes.size());
    ASSERT_EQ(actual.instances.size(), expected.instances.size());
    ASSERT_EQ(actual.materials.size(), expected.materials.size());
    ASSERT_EQ(actual.lights.size(), expected.lights.size());
    for (size_t m = 0; m < expected.meshes.size(); ++m) {
        const Mesh& a = actual.meshes[m];
        const Mesh& e = expected.meshes[m];
        EXPECT_EQ(a.name, e.name);
        ASSERT_EQ(a.positions.size(), e.positions.size()) << e.name;
        EXPECT_EQ(a.indices, e.indices) << e.name;
        for (size_t v = 0; v < e.positions.size(); ++v) {
            expectNear(a.positions[v], e.positions[v], kTolerance, e.name + " position");
            expectNear(a.normals[v], e.normals[v], kTolerance, e.name + " normal");
        }
        ASSERT_EQ(a.submeshes.size(), e.submeshes.size());
        for (size_t s = 0; s < e.submeshes.size(); ++s) {
            EXPECT_EQ(a.submeshes[s].material, e.submeshes[s].material);
            EXPECT_EQ(a.submeshes[s].indexCount, e.submeshes[s].indexCount);
        }
    }
    for (size_t i = 0; i < expected.instances.size(); ++i) {
        EXPECT_EQ(actual.instances[i].mesh, expected.instances[i].mesh);
        for (int c = 0; c < 4; ++c) {
            expectNear(glm::vec3(actual.instances[i].transform[c]),
                       glm::vec3(expected.instances[i].transform[c]), kTolerance, "instance transform");
        }
    }
    for (size_t i = 0; i < expected.materials.size(); ++i) {
        const Material& a = actual.materials[i];
        const Material& e = expected.materials[i];
        EXPECT_EQ(a.name, e.name);
        expectNear(glm::vec3(a.baseColor), glm::vec3(e.baseColor), kTolerance, e.name + " base colour");
        expectNear(a.emission, e.emission, kTolerance, e.name + " emission");
        EXPECT_EQ(a.doubleSided, e.doubleSided);
        EXPECT_EQ(a.metallic, e.metallic);
        EXPECT_EQ(a.roughness, e.roughness);
    }
    for (size_t i = 0; i < expected.lights.size(); ++i) {
        EXPECT_EQ(actual.lights[i].type, expected.lights[i].type);
        expectNear(actual.lights[i].strength(), expected.lights[i].strength(), kTolerance, "light strength");
        expectNear(actual.lights[i].position, expected.lights[i].position, kTolerance, "light position");
        expectNear(actual.lights[i].direction, expected.lights[i].direction, kTolerance, "light direction");
    }
    expectNear(actual.camera.position, expected.camera.position, kTolerance, "camera position");
    expectNear(actual.camera.forward, expected.camera.forward, kTolerance, "camera forward");
    expectNear(actual.camera.up, expected.camera.up, kTolerance, "camera up");
    EXPECT_NEAR(actual.camera.fovY, expected.camera.fovY, 1e-6f);
    expectNear(actual.sky, expected.sky, kTolerance, "sky");
    EXPECT_EQ(actual.image.width, expected.image.width);
    EXPECT_EQ(actual.image.height, expected.image.height);
    EXPECT_DOUBLE_EQ(actual.units.metresPerUnit, expected.units.metresPerUnit);
}

TEST(BuiltinFiles, MatchTheirGenerators) {
    const bool update = std::getenv("LUMINA_UPDATE_SCENES") != nullptr;
    const test::TempDir temp;
    for (const BuiltinScene& builtin : builtinScenes()) {
        if (!builtin.make) {
            continue;
        }
        SCOPED_TRACE(std::string(builtin.name));
        const std::string name(builtin.name);
        const Scene generated = builtin.make();
        const std::string gltf = writeGltf(generated);
        const std::string sceneFile = writeSceneFile(generated, name + ".gltf");
        const fs::path committed = test::sourceDir() / "scenes" / name;
        if (update) {
            fs::create_directories(committed);
            std::ofstream(committed / (name + ".gltf"), std::ios::binary) << gltf;
            std::ofstream(committed / (name + ".json"), std::ios::binary) << sceneFile;
        }
        fs::create_directories(temp.path() / name);
        temp.write(name + "/" + name + ".gltf", gltf);
        const fs::path fresh = temp.write(name + "/" + name + ".json", sceneFile);
        const Scene expected = loadSceneFile(fresh);
        expectSameScene(loadSceneFile(committed / (name + ".json")), expected);
        // And the round trip through glTF loses nothing the generator made.
        expectSameScene(expected, generated);
    }
}

} // namespace
} // namespace lumina::scene
