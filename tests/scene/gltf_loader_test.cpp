// glTF loading: normals, primitive modes, instancing and transforms, materials, textures,
// lights, cameras, sparse accessors, GLB.
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"
#include "tests/scene/test_files.h"

#include <gtest/gtest.h>
#include <numbers>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

// A 2 x 2 RGBA PNG: red, green / blue, half-transparent white.
constexpr const char* kPng2x2 = "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAYAAABytg0kAAAAE0lEQVR4nGP4z8DwHwyBNAg0AABJ"
                                "SQl4KKDbdwAAAABJRU5ErkJggg==";

Scene load(const json& doc, const GltfLoadOptions& options = {}) {
    const TempDir dir;
    return loadGltfFile(dir.write("test.gltf", doc.dump()), options);
}

void expectVec(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(glm::length(actual - expected), 0.0f, tolerance)
        << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

TEST(GltfLoader, MissingNormalsAreGeneratedFlat) {
    const Scene scene = load(test::triangleGltf(test::unitQuad()));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.triangleCount(), 2u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) {
        expectVec(n, {0.0f, 0.0f, 1.0f});
    }
    EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
    EXPECT_TRUE(scene.report.warnings.empty());
}

TEST(GltfLoader, IndexedMeshWithoutNormalsGetsFlatNormalsPerFace) {
    // A tent: two triangles sharing an edge at different angles.
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0.5f, 1, 0, 0.5f, 1, -1};
    const Scene scene = load(test::triangleGltf(positions, {0, 1, 2, 2, 1, 3}));
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.positions.size(), 6u); // de-indexed: a vertex per corner
    expectVec(mesh.normals[0], {0, 0, 1});
    expectVec(mesh.normals[3], glm::normalize(glm::cross(glm::vec3(0.5f, -1, 0), glm::vec3(0, 0, -1))));
}

TEST(GltfLoader, GivenNormalsAreNormalised) {
    json doc = test::triangleGltf(test::unitQuad());
    const std::vector<float> normals(18, 0.0f);
    std::vector<float> scaled = normals;
    for (size_t i = 2; i < scaled.size(); i += 3) {
        scaled[i] = 3.0f;
    }
    const std::vector<uint8_t> bytes = test::gltfBuffer(test::unitQuad());
    std::vector<uint8_t> all = bytes;
    all.resize(bytes.size() + scaled.size() * 4);
    std::memcpy(all.data() + bytes.size(), scaled.data(), scaled.size() * 4);
    doc["buffers"][0] = {{"byteLength", all.size()},
                         {"uri", "data:application/octet-stream;base64," + test::base64(all)}};
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", scaled.size() * 4}});
    doc["accessors"].push_back({{"bufferView", 1}, {"componentType", 5126}, {"count", 6}, {"type", "VEC3"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1;
    const Scene scene = load(doc);
    for (const glm::vec3& n : scene.meshes[0].normals) {
        expectVec(n, {0, 0, 1});
    }
    EXPECT_EQ(scene.report.normalsRepaired, 0u);
}

TEST(GltfLoader, StripsAndFansBecomeLists) {
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0};
    json strip = test::triangleGltf(positions);
    strip["meshes"][0]["primitives"][0]["mode"] = 5;
    const Scene stripScene = load(strip);
    EXPECT_EQ(stripScene.triangleCount(), 3u);
    // Every strip triangle keeps the front face +z.
    for (const glm::vec3& n : stripScene.meshes[0].normals) {
        expectVec(n, {0, 0, 1});
    }
    json fan = test::triangleGltf({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0.5f, 0});
    fan["meshes"][0]["primitives"][0]["mode"] = 6;
    const Scene fanScene = load(fan);
    EXPECT_EQ(fanScene.triangleCount(), 3u);
    for (const glm::vec3& n : fanScene.meshes[0].normals) {
        expectVec(n, {0, 0, 1});
    }
}

TEST(GltfLoader, InstancesShareMeshesAndComposeTransforms) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["nodes"] = json::array({
        {{"name", "parent"}, {"translation", {10, 0, 0}}, {"children", {1, 2}}},
        {{"name", "child"}, {"mesh", 0}, {"scale", {2, 2, 2}}, {"rotation", {0, 0.7071068, 0, 0.7071068}}},
        {{"name", "matrix"}, {"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}}},
        {{"name", "root"}, {"mesh", 0}},
    });
    doc["scenes"][0]["nodes"] = {0, 3};
    const Scene scene = load(doc);
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 3u);
    EXPECT_EQ(scene.triangleCount(), 6u);
    EXPECT_EQ(scene.meshTriangleCount(), 2u);
    EXPECT_EQ(scene.instances[0].name, "child");
    // child: translate (10,0,0) * rotate 90 deg about y * scale 2; its (1,0,0) lands at (10,0,-2).
    expectVec(glm::vec3(scene.instances[0].transform * glm::vec4(1, 0, 0, 1)), {10, 0, -2});
    expectVec(glm::vec3(scene.instances[1].transform * glm::vec4(0, 0, 0, 1)), {10, 5, 0});
    expectVec(glm::vec3(scene.instances[2].transform * glm::vec4(1, 1, 0, 1)), {1, 1, 0});
    const Bounds bounds = scene.worldBounds();
    expectVec(bounds.min, {0, 0, -2});
    expectVec(bounds.max, {11, 6, 0});
}

TEST(GltfLoader, UnreferencedMeshesAreDropped) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["meshes"].push_back(doc["meshes"][0]);
    const Scene scene = load(doc);
    EXPECT_EQ(scene.meshes.size(), 1u);
}

TEST(GltfLoader, NoScenesDrawsEveryRootNode) {
    json doc = test::triangleGltf(test::unitQuad());
    doc.erase("scene");
    doc.erase("scenes");
    doc["nodes"].push_back({{"mesh", 0}, {"translation", {3, 0, 0}}});
    const Scene scene = load(doc);
    EXPECT_EQ(scene.instances.size(), 2u);
}

TEST(GltfLoader, MaterialsKeepFactorsAndEmissiveStrength) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    doc["materials"][0] = {
        {"name", "lamp"},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.75}}},
        {"emissiveFactor", {1.0, 0.5, 0.25}},
        {"doubleSided", true},
        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}}}}};
    const Scene scene = load(doc);
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "lamp");
    expectVec(glm::vec3(m.baseColor), {0.2f, 0.4f, 0.6f});
    expectVec(m.emission, {8.0f, 4.0f, 2.0f});
    EXPECT_FLOAT_EQ(m.metallic, 0.25f);
    EXPECT_FLOAT_EQ(m.roughness, 0.75f);
    EXPECT_TRUE(m.doubleSided);
}

TEST(GltfLoader, PrimitiveWithoutMaterialGetsTheDefault) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["meshes"][0]["primitives"][0].erase("material");
    const Scene scene = load(doc);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].name, "default");
    EXPECT_EQ(scene.meshes[0].submeshes[0].material, 1u);
    EXPECT_EQ(scene.materials[1].baseColor, glm::vec4(1.0f));
}

TEST(GltfLoader, TexturesAreDecodedToRgba8) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["images"] = {{{"name", "checker"}, {"uri", std::string("data:image/png;base64,") + kPng2x2}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
    const Scene scene = load(doc);
    ASSERT_EQ(scene.textures.size(), 1u); // both slots use one image
    const Texture& texture = scene.textures[0];
    EXPECT_EQ(texture.name, "checker");
    EXPECT_EQ(texture.width, 2u);
    EXPECT_EQ(texture.height, 2u);
    ASSERT_EQ(texture.rgba8.size(), 16u);
    EXPECT_EQ(std::vector<uint8_t>(texture.rgba8.begin(), texture.rgba8.begin() + 4),
              (std::vector<uint8_t>{255, 0, 0, 255}));
    EXPECT_EQ(texture.rgba8[15], 128);
    EXPECT_EQ(scene.materials[0].baseColorTexture, 0u);
    EXPECT_EQ(scene.materials[0].emissionTexture, 0u);
}

TEST(GltfLoader, TextureBudgetIsEnforced) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["images"] = {{{"uri", std::string("data:image/png;base64,") + kPng2x2}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    EXPECT_THROW(load(doc, {.maxTextureBytes = 8}), SceneError);
    EXPECT_EQ(load(doc, {.maxTextureBytes = 16}).textures.size(), 1u);
}

TEST(GltfLoader, ExternalTextureAndBufferFilesAreRead) {
    const TempDir dir;
    json doc = test::triangleGltf(test::unitQuad());
    const std::vector<uint8_t> bin = test::gltfBuffer(test::unitQuad());
    dir.write("quad.bin", bin);
    doc["buffers"][0]["uri"] = "quad.bin";
    std::string png;
    {
        // Decode the base64 PNG into a file beside the glTF.
        const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        uint32_t bits = 0;
        int count = 0;
        for (const char c : std::string(kPng2x2)) {
            if (c == '=') {
                break;
            }
            bits = bits << 6 | uint32_t(alphabet.find(c));
            if ((count += 6) >= 8) {
                png += char((bits >> (count -= 8)) & 0xff);
            }
        }
    }
    dir.write("texture.png", png);
    doc["images"] = {{{"uri", "texture.png"}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const Scene scene = loadGltfFile(dir.write("scene.gltf", doc.dump()));
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].name, "texture.png");
    EXPECT_EQ(scene.textures[0].width, 2u);
}

TEST(GltfLoader, PunctualLightsConvertToSceneUnits) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights",
           {{{"name", "bulb"}, {"type", "point"}, {"intensity", 2.0}, {"color", {1, 0.5, 0}}, {"range", 7}},
            {{"name", "sun"}, {"type", "directional"}, {"intensity", 1000.0}},
            {{"name", "cone"},
             {"type", "spot"},
             {"intensity", 3.0},
             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}}}}}}};
    // Point at (0, 2, 0); sun turned 90 degrees about x (shining along -y... from -z: +y
    // rotated); spot at (1, 1, 1) looking along -z.
    doc["nodes"].push_back(
        {{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["nodes"].push_back({{"rotation", {-0.7071068, 0, 0, 0.7071068}},
                            {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    doc["nodes"].push_back(
        {{"translation", {1, 1, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    doc["scenes"][0]["nodes"] = {0, 1, 2, 3};
    const Scene scene = load(doc, {.metresPerUnit = 0.01}); // centimetres
    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& bulb = scene.lights[0];
    EXPECT_EQ(bulb.type, LightType::Point);
    expectVec(bulb.position, {0, 2, 0});
    // 2 cd in a scene of centimetres: irradiance 2/d_m^2 = 2/(0.01 d)^2, so I = 20000.
    EXPECT_NEAR(bulb.intensity, 20000.0f, 1e-2f);
    expectVec(bulb.color, {1, 0.5f, 0});
    EXPECT_EQ(bulb.range, 7.0f);
    const Light& sun = scene.lights[1];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.intensity, 1000.0f); // lux are not length-dependent
    expectVec(sun.direction, {0, -1, 0});
    const Light& cone = scene.lights[2];
    EXPECT_EQ(cone.type, LightType::Spot);
    expectVec(cone.direction, {0, 0, -1});
    EXPECT_FLOAT_EQ(cone.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(cone.outerConeAngle, 0.4f);
}

TEST(GltfLoader, FirstPerspectiveCameraIsUsed) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["cameras"] = {{{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                      {{"name", "eye"},
                       {"type", "perspective"},
                       {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 2.0}}}}};
    doc["nodes"].push_back({{"camera", 0}});
    doc["nodes"].push_back({{"camera", 1}, {"translation", {0, 0, 5}}});
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene scene = load(doc);
    EXPECT_TRUE(scene.cameraFromFile);
    EXPECT_EQ(scene.camera.name, "eye");
    EXPECT_FLOAT_EQ(scene.camera.fovY, 0.5f);
    expectVec(scene.camera.position, {0, 0, 5});
    expectVec(scene.camera.forward, {0, 0, -1});
    EXPECT_GT(scene.camera.farPlane, 5.0f); // infinite zfar made finite beyond the scene
    EXPECT_EQ(scene.image.width, 2 * scene.image.height);
    EXPECT_FALSE(scene.report.warnings.empty()); // the orthographic camera
}

TEST(GltfLoader, WithoutACameraOneFramesTheScene) {
    const Scene scene = load(test::triangleGltf(test::unitQuad()));
    EXPECT_FALSE(scene.cameraFromFile);
    expectVec(scene.camera.forward, {0, 0, -1});
    EXPECT_GT(scene.camera.position.z, 1.0f);
    EXPECT_GT(scene.camera.farPlane, scene.camera.nearPlane);
}

TEST(GltfLoader, SparseAccessorsSubstituteValues) {
    json doc = test::triangleGltf(test::unitQuad());
    // Move vertex 2 (1,1,0) to (2,2,0) through a sparse substitution.
    const std::vector<uint8_t> quad = test::gltfBuffer(test::unitQuad());
    std::vector<uint8_t> all = quad;
    const uint32_t index = 2;
    const float value[3] = {2, 2, 0};
    all.resize(quad.size() + 16);
    std::memcpy(all.data() + quad.size(), &index, 4);
    std::memcpy(all.data() + quad.size() + 4, value, 12);
    doc["buffers"][0] = {{"byteLength", all.size()},
                         {"uri", "data:application/octet-stream;base64," + test::base64(all)}};
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", quad.size()}, {"byteLength", 4}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", quad.size() + 4}, {"byteLength", 12}});
    doc["accessors"][0]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", 1}, {"componentType", 5125}}},
                                     {"values", {{"bufferView", 2}}}};
    const Scene scene = load(doc);
    expectVec(scene.meshes[0].bounds.max, {2, 2, 0});
}

TEST(GltfLoader, GlbWithBinChunkLoads) {
    json doc = test::triangleGltf(test::unitQuad(), {0, 1, 2, 3, 4, 5});
    const std::vector<uint8_t> bin = test::gltfBuffer(test::unitQuad(), {0, 1, 2, 3, 4, 5});
    doc["buffers"][0].erase("uri");
    const TempDir dir;
    const Scene scene = loadGltfFile(dir.write("quad.glb", test::makeGlb(doc, bin)));
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.name, "quad");
}

TEST(GltfLoader, MultiplePrimitivesBecomeSubmeshes) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["materials"].push_back({{"name", "second"}});
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"material", 1}});
    const Scene scene = load(doc);
    ASSERT_EQ(scene.meshes[0].submeshes.size(), 2u);
    EXPECT_EQ(scene.meshes[0].submeshes[1].material, 1u);
    EXPECT_EQ(scene.meshes[0].submeshes[1].firstIndex, 6u);
    EXPECT_EQ(scene.triangleCount(), 4u);
}

TEST(GltfLoader, MemoryLoadCanForbidExternalFiles) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["buffers"][0]["uri"] = "/etc/hostname";
    const std::string text = doc.dump();
    const std::vector<uint8_t> bytes(text.begin(), text.end());
    try {
        loadGltfMemory(bytes, false, "fuzz.gltf", "/", {.allowExternalFiles = false});
        FAIL() << "external file was read";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), "fuzz.gltf");
    }
}

} // namespace
} // namespace lumina::scene
