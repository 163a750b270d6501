// Bad input: each case is an error naming the file and the problem, or a documented repair
// (docs/scenes.md, "Bad input") reported in Scene::report; never a crash.
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_loader.h"
#include "tests/scene/test_files.h"

#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

// Loads `file` expecting a SceneError that names it and contains `problem`.
void expectError(const fs::path& file, const std::string& problem) {
    try {
        loadGltfFile(file);
        ADD_FAILURE() << file << " loaded; expected an error containing '" << problem << "'";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), file);
        const std::string message = error.what();
        EXPECT_NE(message.find(file.generic_string()), std::string::npos) << message;
        EXPECT_NE(message.find(problem), std::string::npos) << "expected '" << problem << "' in: " << message;
    }
}

void expectError(const json& doc, const std::string& problem) {
    const TempDir dir;
    expectError(dir.write("bad.gltf", doc.dump()), problem);
}

bool hasWarning(const Scene& scene, const std::string& text) {
    for (const std::string& warning : scene.report.warnings) {
        if (warning.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

json quad() {
    return test::triangleGltf(test::unitQuad());
}

TEST(BadInput, TruncatedGlb) {
    json doc = test::triangleGltf(test::unitQuad());
    doc["buffers"][0].erase("uri");
    const std::vector<uint8_t> glb = test::makeGlb(doc, test::gltfBuffer(test::unitQuad()));
    const TempDir dir;
    for (const size_t size : {size_t(0), size_t(7), size_t(20), glb.size() / 2, glb.size() - 4}) {
        SCOPED_TRACE(size);
        const fs::path file =
            dir.write("truncated.glb", std::vector<uint8_t>(glb.begin(), glb.begin() + long(size)));
        expectError(file, size == 0 ? "empty" : "truncated GLB");
    }
}

TEST(BadInput, NotAGlb) {
    const TempDir dir;
    expectError(dir.write("text.glb", std::string("this is not a binary glTF file at all")),
                "not a GLB file");
}

TEST(BadInput, MalformedJson) {
    const TempDir dir;
    expectError(dir.write("bad.gltf", std::string("{ \"asset\": { \"version\": \"2.0\" ")), "malformed JSON");
    expectError(dir.write("array.gltf", std::string("[1, 2]")), "not a JSON object");
    const std::string text = quad().dump();
    expectError(dir.write("cut.gltf", text.substr(0, text.size() / 2)), "malformed JSON");
}

TEST(BadInput, DeeplyNestedJson) {
    std::string text = "{\"asset\": {\"version\": \"2.0\"}, \"extras\": ";
    text += std::string(10000, '[') + std::string(10000, ']') + "}";
    const TempDir dir;
    expectError(dir.write("deep.gltf", text), "nests deeper");
}

TEST(BadInput, MissingBuffer) {
    json doc = quad();
    doc["buffers"][0]["uri"] = "missing.bin";
    expectError(doc, "missing.bin");
}

TEST(BadInput, BufferFileTooShort) {
    const TempDir dir;
    json doc = quad();
    dir.write("short.bin", std::vector<uint8_t>(8, 0));
    doc["buffers"][0]["uri"] = "short.bin";
    expectError(dir.write("bad.gltf", doc.dump()), "short.bin");
}

TEST(BadInput, MissingTexture) {
    json doc = quad();
    doc["images"] = {{{"uri", "missing.png"}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    expectError(doc, "missing.png");
}

TEST(BadInput, UndecodableTexture) {
    json doc = quad();
    doc["images"] = {{{"uri", "data:image/png;base64,AAAAAAAA"}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
    expectError(doc, "cannot decode");
}

TEST(BadInput, TextureIndexOutOfRange) {
    json doc = quad();
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 4}};
    expectError(doc, "texture 4 does not exist");
}

TEST(BadInput, ImageBufferViewOutsideItsBuffer) {
    json doc = quad();
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 1000}});
    doc["images"] = {{{"bufferView", 1}, {"mimeType", "image/png"}}};
    expectError(doc, "does not fit buffer");
}

TEST(BadInput, PointsAndLinesAreSkipped) {
    json doc = quad();
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
    const TempDir dir;
    const Scene scene = loadGltfFile(dir.write("mixed.gltf", doc.dump()));
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.report.nonTrianglePrimitivesSkipped, 2u);
    EXPECT_TRUE(hasWarning(scene, "lines skipped"));
    EXPECT_TRUE(hasWarning(scene, "points skipped"));

    json only = quad();
    only["meshes"][0]["primitives"][0]["mode"] = 3;
    expectError(only, "points and lines are skipped");
}

TEST(BadInput, UnknownPrimitiveMode) {
    json doc = quad();
    doc["meshes"][0]["primitives"][0]["mode"] = 9;
    expectError(doc, "unknown primitive mode 9");
}

TEST(BadInput, NonFinitePositions) {
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        std::vector<float> positions = test::unitQuad();
        positions[4] = bad;
        expectError(test::triangleGltf(positions), "not finite");
    }
}

TEST(BadInput, DegenerateTrianglesAreDropped) {
    std::vector<float> positions = test::unitQuad();
    // A triangle with a repeated corner and one with three collinear corners.
    positions.insert(positions.end(), {0, 0, 0, 0, 0, 0, 1, 1, 0});
    positions.insert(positions.end(), {0, 0, 0, 1, 1, 0, 2, 2, 0});
    const TempDir dir;
    const Scene scene = loadGltfFile(dir.write("degenerate.gltf", test::triangleGltf(positions).dump()));
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.report.degenerateTrianglesDropped, 2u);
    EXPECT_TRUE(hasWarning(scene, "2 degenerate triangle(s) dropped"));
    // Repeated indices too.
    const Scene indexed = loadGltfFile(
        dir.write("indexed.gltf", test::triangleGltf(test::unitQuad(), {0, 1, 2, 3, 4, 5, 0, 0, 1}).dump()));
    EXPECT_EQ(indexed.report.degenerateTrianglesDropped, 1u);
}

TEST(BadInput, OnlyDegenerateTrianglesIsAnEmptyScene) {
    expectError(test::triangleGltf({0, 0, 0, 1, 0, 0, 2, 0, 0}), "the scene is empty");
}

TEST(BadInput, ZeroScaleInstanceIsDropped) {
    json doc = quad();
    doc["nodes"].push_back({{"mesh", 0}, {"scale", {0, 0, 0}}, {"name", "flat"}});
    doc["scenes"][0]["nodes"] = {0, 1};
    const TempDir dir;
    const Scene scene = loadGltfFile(dir.write("zero.gltf", doc.dump()));
    EXPECT_EQ(scene.instances.size(), 1u);
    EXPECT_TRUE(hasWarning(scene, "'flat': zero scale"));

    json only = quad();
    only["nodes"][0]["scale"] = {0, 1, 1};
    expectError(only, "the scene is empty");
}

TEST(BadInput, HugeScale) {
    json doc = quad();
    doc["nodes"][0]["scale"] = {1e20, 1e20, 1e20};
    expectError(doc, "huge scale");
    json nested = quad();
    nested["nodes"] = {{{"scale", {1e200, 1e200, 1e200}}, {"children", {1}}},
                       {{"mesh", 0}, {"scale", {1e200, 1e200, 1e200}}}};
    expectError(nested, "overflows");
    json matrix = quad();
    matrix["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1e9, 0, 0, 1};
    expectError(matrix, "beyond the supported");
}

TEST(BadInput, NonFiniteTransform) {
    json doc = quad();
    doc["nodes"][0]["translation"] = {0, 12345, 0};
    std::string text = doc.dump();
    text.replace(text.find("12345"), 5, "1e400"); // beyond double: JSON has no infinity
    const TempDir dir;
    expectError(dir.write("inf.gltf", text), "malformed JSON");
}

TEST(BadInput, EmptyScene) {
    expectError(json{{"asset", {{"version", "2.0"}}}}, "the scene is empty");
    json noNodes = quad();
    noNodes["scenes"][0]["nodes"] = json::array();
    expectError(noNodes, "the scene is empty");
    const TempDir dir;
    expectError(dir.write("empty.gltf", std::string()), "the file is empty");
}

TEST(BadInput, IndexOutOfRange) {
    expectError(test::triangleGltf(test::unitQuad(), {0, 1, 2, 3, 4, 6}),
                "index 5 is 6, out of range for 6 vertices");
}

TEST(BadInput, AccessorOutsideItsBufferView) {
    json doc = quad();
    doc["accessors"][0]["count"] = 7;
    expectError(doc, "run past the end of bufferView");
    json offset = quad();
    offset["accessors"][0]["byteOffset"] = 4;
    expectError(offset, "run past the end of bufferView");
    json view = quad();
    view["bufferViews"][0]["byteLength"] = 4096;
    expectError(view, "bufferView");
    json stride = quad();
    stride["bufferViews"][0]["byteStride"] = 8;
    expectError(stride, "byteStride");
}

TEST(BadInput, HugeAccessorWithoutData) {
    json doc = quad();
    doc["accessors"][0].erase("bufferView");
    doc["accessors"][0]["count"] = 50'000'000;
    expectError(doc, "allowed without data");
    json huge = quad();
    huge["accessors"][0]["count"] = 1ull << 40;
    expectError(huge, "more than the supported");
}

TEST(BadInput, BudgetsBoundWhatAFileCanAllocate) {
    json doc = quad();
    for (int i = 0; i < 10; ++i) {
        doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
    }
    const TempDir dir;
    const fs::path file = dir.write("many.gltf", doc.dump());
    EXPECT_EQ(loadGltfFile(file).triangleCount(), 22u);
    try {
        loadGltfFile(file, {.maxVertices = 30});
        ADD_FAILURE() << "vertex budget not applied";
    } catch (const SceneError& error) {
        EXPECT_NE(std::string(error.what()).find("more than 30 vertices in all"), std::string::npos)
            << error.what();
    }
}

TEST(BadInput, WrongAccessorType) {
    json doc = quad();
    doc["accessors"][0]["type"] = "VEC2";
    expectError(doc, "should be VEC3");
    json indices = test::triangleGltf(test::unitQuad(), {0, 1, 2, 3, 4, 5});
    indices["accessors"][1]["componentType"] = 5126;
    expectError(indices, "componentType 5126");
}

TEST(BadInput, MissingPosition) {
    json doc = quad();
    doc["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
    expectError(doc, "has no POSITION");
}

TEST(BadInput, BadReferences) {
    json material = quad();
    material["meshes"][0]["primitives"][0]["material"] = 3;
    expectError(material, "material 3 does not exist");
    json mesh = quad();
    mesh["nodes"][0]["mesh"] = 5;
    expectError(mesh, "mesh 5 does not exist");
    json child = quad();
    child["nodes"][0]["children"] = {7};
    expectError(child, "child 7 does not exist");
    json sceneIndex = quad();
    sceneIndex["scene"] = 3;
    expectError(sceneIndex, "default scene 3 does not exist");
    json root = quad();
    root["scenes"][0]["nodes"] = {0, 0};
    expectError(root, "lists root node 0 twice");
}

TEST(BadInput, NodeCycleAndSharedChild) {
    json cycle = quad();
    cycle["nodes"] = {{{"children", {1}}}, {{"children", {0}}, {"mesh", 0}}};
    expectError(cycle, "not a tree");
    json shared = quad();
    shared["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
    shared["scenes"][0]["nodes"] = {0, 1};
    expectError(shared, "more than one parent");
    json self = quad();
    self["nodes"][0]["children"] = {0};
    expectError(self, "not a tree");
}

TEST(BadInput, VertexCountNotAMultipleOfThree) {
    std::vector<float> positions = test::unitQuad();
    positions.insert(positions.end(), {5, 5, 5, 6, 6, 6});
    const TempDir dir;
    const Scene scene = loadGltfFile(dir.write("ragged.gltf", test::triangleGltf(positions).dump()));
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_TRUE(hasWarning(scene, "the last 2 are ignored"));
}

TEST(BadInput, BadMaterialValues) {
    json doc = quad();
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, -1, 0.5, 1};
    expectError(doc, "baseColorFactor component 1");
    json rough = quad();
    rough["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 3;
    expectError(rough, "roughnessFactor");
    json strength = quad();
    strength["materials"][0]["extensions"] = {
        {"KHR_materials_emissive_strength", {{"emissiveStrength", -2}}}};
    expectError(strength, "emissiveStrength");
}

TEST(BadInput, BadLights) {
    json doc = quad();
    doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "area"}, {"intensity", 1}}}}}}};
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["scenes"][0]["nodes"] = {0, 1};
    expectError(doc, "");
    json missing = quad();
    missing["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 2}}}};
    expectError(missing, "names a light that does not exist");
}

TEST(BadInput, UnsupportedVersionAndExtensions) {
    json v1 = quad();
    v1["asset"]["version"] = "1.0";
    expectError(v1, "glTF version '1.0' is not supported");
    json draco = quad();
    draco["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectError(draco, "requires extension KHR_draco_mesh_compression");
}

TEST(BadInput, MissingOrDirectoryFile) {
    const TempDir dir;
    expectError(dir.path() / "nothing.gltf", "no such file");
    expectError(dir.path(), "not a regular file");
}

} // namespace
} // namespace lumina::scene
