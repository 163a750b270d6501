// Real files from Debian's assimp-testmodels package (CI installs it): good models load with
// the content they hold, broken ones fail with errors naming the file and the problem, and
// no file of the package makes the loader throw anything but a SceneError.
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"
#include "tests/scene/test_files.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;

class AssimpModels : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::is_directory(test::assimpModels() / "glTF2")) {
            GTEST_SKIP() << "assimp-testmodels is not installed (" << test::assimpModels() << ")";
        }
    }
    static fs::path model(const std::string& relative) { return test::assimpModels() / relative; }

    static std::string errorOf(const fs::path& file) {
        try {
            loadGltfFile(file);
        } catch (const SceneError& error) {
            EXPECT_EQ(error.file(), file);
            return error.what();
        }
        ADD_FAILURE() << file << " loaded";
        return {};
    }
};

TEST_F(AssimpModels, TwoCylinderEngineLoads) {
    const Scene scene = loadGltfFile(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(scene.meshes.size(), 29u);
    EXPECT_EQ(scene.instances.size(), 67u); // of its 82 nodes
    EXPECT_EQ(scene.materials.size(), 34u);
    EXPECT_EQ(scene.meshTriangleCount(), 65311u);
    EXPECT_EQ(scene.triangleCount(), 110336u);
    // The file holds 10413 triangles with a repeated index and 6 of zero area.
    EXPECT_EQ(scene.report.degenerateTrianglesDropped, 10419u);
    for (const Mesh& mesh : scene.meshes) {
        for (const glm::vec3& n : mesh.normals) {
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
        }
    }
}

TEST_F(AssimpModels, BadNormalsAreRegenerated) {
    const Scene scene = loadGltfFile(model("glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb"));
    EXPECT_EQ(scene.triangleCount(), 12u);
    EXPECT_GT(scene.report.normalsRepaired, 0u);
    for (const glm::vec3& n : scene.meshes[0].normals) {
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
}

TEST_F(AssimpModels, InfinitePositionsAreAnError) {
    const std::string message = errorOf(model("glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"));
    EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

TEST_F(AssimpModels, IncorrectVertexArraysAreRepaired) {
    // Eight meshes: cubes and line sets, some with 35 vertices or indices (not a multiple of 3).
    const Scene scene = loadGltfFile(model("glTF2/IncorrectVertexArrays/Cube.gltf"));
    EXPECT_EQ(scene.triangleCount(), 12u + 11u + 12u + 11u);
    EXPECT_EQ(scene.report.nonTrianglePrimitivesSkipped, 4u);
    EXPECT_EQ(scene.instances.size(), 4u);
}

TEST_F(AssimpModels, GltfOneIsRefused) {
    EXPECT_NE(
        errorOf(model("glTF/IncorrectVertexArrays/Cube_v1.gltf")).find("glTF version '1.0' is not supported"),
        std::string::npos);
    EXPECT_NE(errorOf(model("glTF/BoxTextured-glTF-Binary/BoxTextured.glb")).find("version 1"),
              std::string::npos);
}

TEST_F(AssimpModels, IndexOutOfRange) {
    EXPECT_NE(errorOf(model("glTF2/IndexOutOfRange/IndexOutOfRange.gltf")).find("out of range"),
              std::string::npos);
    EXPECT_NE(errorOf(model("glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf")).find("out of range"),
              std::string::npos);
}

TEST_F(AssimpModels, MissingBinIsNamed) {
    EXPECT_NE(errorOf(model("glTF2/MissingBin/BoxTextured.gltf")).find("BoxTextured0.bin"),
              std::string::npos);
}

TEST_F(AssimpModels, RecursiveNodesAreAnError) {
    EXPECT_NE(errorOf(model("glTF2/RecursiveNodes/RecursiveNodes.gltf")).find("not a tree"),
              std::string::npos);
}

TEST_F(AssimpModels, ScenesWithoutNodesAreEmpty) {
    EXPECT_NE(errorOf(model("glTF2/TestNoRootNode/SceneWithoutNodes.gltf")).find("empty"), std::string::npos);
    EXPECT_NE(errorOf(model("glTF2/TestNoRootNode/NoScene.gltf")).find("empty"), std::string::npos);
}

TEST_F(AssimpModels, DracoIsRefusedByName) {
    EXPECT_NE(errorOf(model("glTF2/draco/2CylinderEngine.gltf")).find("KHR_draco_mesh_compression"),
              std::string::npos);
}

TEST_F(AssimpModels, TexturesFromFilesChunksAndDataUris) {
    for (const char* file :
         {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
          "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = loadGltfFile(model(file));
        EXPECT_EQ(scene.triangleCount(), 12u);
        ASSERT_EQ(scene.textures.size(), 1u);
        EXPECT_EQ(scene.textures[0].width, 211u); // CesiumLogoFlat.png, palette PNG to RGBA8
        EXPECT_EQ(scene.textures[0].height, 211u);
        EXPECT_EQ(scene.textures[0].rgba8.size(), 211u * 211u * 4u);
        EXPECT_EQ(scene.materials[0].baseColorTexture, 0u);
    }
}

TEST_F(AssimpModels, CamerasFile) {
    const Scene scene = loadGltfFile(model("glTF2/cameras/Cameras.gltf"));
    EXPECT_TRUE(scene.cameraFromFile);
    EXPECT_FLOAT_EQ(scene.camera.fovY, 0.7f);
    EXPECT_NEAR(scene.camera.position.z, 3.0f, 1e-6f);
}

// Every glTF of the package either loads or fails with a SceneError: nothing else escapes.
TEST_F(AssimpModels, EveryFileLoadsOrFailsCleanly) {
    size_t loaded = 0, failed = 0;
    for (const auto& entry : fs::recursive_directory_iterator(test::assimpModels())) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".gltf" && extension != ".glb")) {
            continue;
        }
        SCOPED_TRACE(entry.path().string());
        try {
            const Scene scene = loadGltfFile(entry.path());
            EXPECT_GT(scene.triangleCount(), 0u);
            ++loaded;
        } catch (const SceneError& error) {
            EXPECT_EQ(error.file(), entry.path());
            ++failed;
        }
    }
    EXPECT_GT(loaded, 20u);
    EXPECT_GT(failed, 10u);
}

} // namespace
} // namespace lumina::scene
