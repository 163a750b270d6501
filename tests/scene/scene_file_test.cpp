// Scene files: overrides apply, units convert, and every mistake names the key and the file.
#include "gi/scene/generators/generators.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_file.h"
#include "gi/scene/scene_loader.h"
#include "tests/scene/test_files.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// The error `load` throws, which must name `file`; empty when it throws none.
template <typename Load>
std::string errorOf(Load load, const fs::path& file) {
    try {
        load();
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), file);
        EXPECT_NE(std::string(error.what()).find(file.generic_string()), std::string::npos) << error.what();
        return error.what();
    }
    ADD_FAILURE() << "no SceneError for " << file;
    return {};
}

fs::path cornellGltf() {
    return test::sourceDir() / "scenes" / "cornell_box" / "cornell_box.gltf";
}

std::string sceneFile(const std::string& extra) {
    return "{ \"gltf\": \"" + cornellGltf().generic_string() + "\", \"metresPerUnit\": 0.001" + extra + " }";
}

TEST(SceneFile, UnknownKeyNamesKeyAndFile) {
    const TempDir dir;
    const fs::path file = dir.write("typo.json", sceneFile(", \"skye\": [0, 0, 0]"));
    const std::string message = errorOf([&] { loadScene(file.string()); }, file);
    EXPECT_NE(message.find("unknown key 'skye'"), std::string::npos) << message;
    EXPECT_NE(message.find("known keys"), std::string::npos) << message;
}

TEST(SceneFile, UnknownNestedKeyNamesItsPath) {
    const TempDir dir;
    const fs::path file = dir.write("typo.json", sceneFile(", \"camera\": {\"fov\": 40}"));
    const std::string message = errorOf([&] { loadScene(file.string()); }, file);
    EXPECT_NE(message.find("'camera.fov'"), std::string::npos) << message;
    const fs::path light =
        dir.write("light.json",
                  sceneFile(", \"lights\": [{\"type\": \"point\", \"position\": [0,0,0], \"intensity\": 1, "
                            "\"colour\": [1,1,1]}]"));
    EXPECT_NE(errorOf([&] { loadScene(light.string()); }, light).find("'lights[0].colour'"),
              std::string::npos);
}

TEST(SceneFile, OverridesApply) {
    const TempDir dir;
    const fs::path file = dir.write("override.json", sceneFile(R"(,
        "description": "test",
        "camera": {"position": [278, 273, -500], "lookAt": [278, 273, 0], "fovYDegrees": 50, "near": 1, "far": 5000},
        "lights": [{"name": "bulb", "type": "point", "position": [278, 500, 280], "color": [1, 0.5, 0.25],
                    "intensity": 0.002, "range": 900},
                   {"type": "spot", "position": [0, 500, 0], "direction": [0, -1, 0], "intensity": 1,
                    "innerConeDegrees": 10, "outerConeDegrees": 20}],
        "sun": {"direction": [0, -1, 1], "illuminance": 5, "color": [1, 0.9, 0.8]},
        "sky": [0.1, 0.2, 0.3],
        "image": {"width": 320, "height": 200},
        "technique": "screen_probes",
        "preset": "high"
    )"));
    const Scene scene = loadScene(file.string());
    EXPECT_EQ(scene.description, "test");
    EXPECT_EQ(scene.name, "override");
    EXPECT_EQ(scene.sourceFile, file);
    EXPECT_NEAR(scene.camera.position.z, -500.0f, 1e-4f);
    EXPECT_NEAR(scene.camera.forward.z, 1.0f, 1e-6f);
    EXPECT_NEAR(glm::degrees(scene.camera.fovY), 50.0f, 1e-4f);
    EXPECT_EQ(scene.camera.nearPlane, 1.0f);
    EXPECT_EQ(scene.camera.farPlane, 5000.0f);
    ASSERT_EQ(scene.lights.size(), 3u);
    // Candela to scene units with 1 mm units: I = 0.002 / 0.001^2 = 2000 (units.h).
    EXPECT_EQ(scene.lights[0].name, "bulb");
    EXPECT_NEAR(scene.lights[0].intensity, 2000.0f, 1e-2f);
    EXPECT_EQ(scene.lights[0].color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(scene.lights[0].range, 900.0f);
    EXPECT_EQ(scene.lights[1].type, LightType::Spot);
    EXPECT_NEAR(scene.lights[1].outerConeAngle, glm::radians(20.0f), 1e-6f);
    EXPECT_EQ(scene.lights[2].type, LightType::Directional);
    EXPECT_EQ(scene.lights[2].name, "sun");
    EXPECT_EQ(scene.lights[2].intensity, 5.0f); // lux carry over unchanged
    EXPECT_NEAR(scene.lights[2].direction.z, std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(scene.sky, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene.image.width, 320u);
    EXPECT_EQ(scene.image.height, 200u);
    EXPECT_EQ(scene.technique, "screen_probes");
    EXPECT_EQ(scene.preset, "high");
    EXPECT_EQ(scene.triangleCount(), 32u);
}

TEST(SceneFile, ReplaceLightsDropsTheGltfsLights) {
    const TempDir dir;
    const fs::path gltf = test::sourceDir() / "scenes" / "cornell_box_point" / "cornell_box_point.gltf";
    const fs::path keep =
        dir.write("keep.json", "{\"gltf\": \"" + gltf.generic_string() + "\", \"metresPerUnit\": 0.001}");
    EXPECT_EQ(loadScene(keep.string()).lights.size(), 1u);
    const fs::path replace =
        dir.write("replace.json", "{\"gltf\": \"" + gltf.generic_string() +
                                      "\", \"replaceLights\": true, \"sun\": {\"direction\": "
                                      "[0, -1, 0], \"illuminance\": 3}}");
    const Scene scene = loadScene(replace.string());
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
}

TEST(SceneFile, PartialCameraOverrideKeepsTheRest) {
    const TempDir dir;
    const fs::path file = dir.write("fov.json", sceneFile(", \"camera\": {\"fovYDegrees\": 30}"));
    const Scene scene = loadScene(file.string());
    EXPECT_NEAR(glm::degrees(scene.camera.fovY), 30.0f, 1e-4f);
    EXPECT_NEAR(glm::length(scene.camera.position - glm::vec3(278.0f, 273.0f, -800.0f)), 0.0f, 1e-3f);
    EXPECT_NEAR(scene.camera.forward.z, 1.0f, 1e-6f);
}

TEST(SceneFile, MistakesAreErrorsNamingTheKey) {
    const TempDir dir;
    const struct {
        const char* json;
        const char* expected;
    } cases[] = {
        {R"({"metresPerUnit": 1})", "exactly one of 'gltf'"},
        {R"({"gltf": "a.gltf", "generator": "city"})", "exactly one of 'gltf'"},
        {R"({"generator": "forest"})", "'generator' must be atrium, city or door"},
        {R"({"generator": "atrium", "instances": 5})", "'instances' applies only"},
        {R"({"generator": "city", "instances": -5})", "'instances' must be a whole number"},
        {R"({"generator": "city", "instances": 0})", "'instances' must be a whole number"},
        {R"({"generator": "city", "doorGap": 0.02})", "'doorGap' applies only"},
        {R"({"generator": "door", "doorGap": 0})", "'doorGap' must be within [0.001, 0.5]"},
        {R"({"generator": "door", "doorGap": 2})", "'doorGap' must be within"},
        {R"({"generator": "door", "doorGap": "wide"})", "'doorGap' must be a finite number"},
        {R"({"generator": "atrium", "metresPerUnit": 0})", "'metresPerUnit' must be positive"},
        {R"({"generator": "atrium", "camera": {"fovYDegrees": "wide"}})",
         "'camera.fovYDegrees' must be a finite"},
        {R"({"generator": "atrium", "camera": {"forward": [0, 0, 0]}})",
         "'camera.forward' must not be a zero"},
        {R"({"generator": "atrium", "camera": {"lookAt": [1, 0, 0], "forward": [1, 0, 0]}})", "cannot both"},
        {R"({"generator": "atrium", "sky": [1, 2]})", "'sky' must be an array of three"},
        {R"({"generator": "atrium", "sky": [-1, 0, 0]})", "'sky' must not be negative"},
        {R"({"generator": "atrium", "image": {"width": 0, "height": 10}})", "'image.width' must be a whole"},
        {R"({"generator": "atrium", "image": {"width": 10}})", "'image.height' is required"},
        {R"({"generator": "atrium", "technique": "Screen Probes"})", "'technique' must be a name"},
        {R"({"generator": "atrium", "lights": [{"type": "area", "intensity": 1}]})",
         "'lights[0].type' must be"},
        {R"({"generator": "atrium", "lights": [{"type": "point", "intensity": 1}]})",
         "'lights[0].position' is required"},
        {R"({"generator": "atrium", "lights": [{"type": "directional", "direction": [0,-1,0]}]})",
         "'lights[0].intensity' is required"},
        {R"({"generator": "atrium", "lights": {}})", "'lights' must be an array"},
        {R"({"generator": "atrium", "sun": {"illuminance": 3}})", "'sun.direction' is required"},
        {R"({"generator": "atrium", "camera": 3})", "'camera' must be a JSON object"},
        {R"({"generator": "atrium", "camera": {"position": [0, 1, 0], "lookAt": [0, 1, 0]}})",
         "camera.lookAt"},
        {R"([1, 2, 3])", "the top level must be a JSON object"},
        {R"({"generator": "atrium", )", "malformed JSON"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.json);
        const fs::path file = dir.write("bad.json", c.json);
        const std::string message = errorOf([&] { loadScene(file.string()); }, file);
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    }
}

TEST(SceneFile, MissingGltfNamesIt) {
    const TempDir dir;
    const fs::path file = dir.write("missing.json", R"({"gltf": "nowhere.gltf"})");
    const fs::path gltf = dir.path() / "nowhere.gltf";
    EXPECT_NE(errorOf([&] { loadScene(file.string()); }, gltf).find("no such file"), std::string::npos);
}

TEST(SceneFile, GltfPathIsRelativeToTheSceneFile) {
    const TempDir dir;
    fs::create_directories(dir.path() / "sub");
    fs::copy_file(cornellGltf(), dir.path() / "sub" / "box.gltf");
    const fs::path file = dir.write("scene.json", R"({"gltf": "sub/box.gltf"})");
    EXPECT_EQ(loadScene(file.string()).triangleCount(), 32u);
}

TEST(SceneFile, CommentsAreAllowed) {
    const SceneFile parsed = parseSceneFileText("{ // the atrium\n \"generator\": \"atrium\" }", "x.json");
    EXPECT_EQ(parsed.generator, "atrium");
}

TEST(SceneFile, InstanceCountAppliesOnlyToTheCity) {
    EXPECT_THROW(loadScene("atrium", {.instances = 5}), SceneError);
    EXPECT_THROW(loadScene("cornell_box", {.instances = 5}), SceneError);
    EXPECT_THROW(loadScene(cornellGltf().string(), {.instances = 5}), SceneError);
    const TempDir dir;
    const fs::path file = dir.write("town.json", R"({"generator": "city", "instances": 9})");
    EXPECT_EQ(loadScene(file.string()).instances.size(), 10u);
    EXPECT_EQ(loadScene(file.string(), {.instances = 3}).instances.size(), 4u);
}

TEST(SceneNames, UnknownNameListsTheBuiltins) {
    const std::string message = errorOf([] { loadScene("cornel_box"); }, "cornel_box");
    EXPECT_NE(message.find("cornell_box"), std::string::npos) << message;
    EXPECT_NE(message.find("furnace_0.99"), std::string::npos) << message;
}

TEST(SceneNames, PathsLoadDirectly) {
    EXPECT_EQ(loadScene(cornellGltf().string()).triangleCount(), 32u);
    const fs::path json = test::sourceDir() / "scenes" / "furnace_0.5" / "furnace_0.5.json";
    EXPECT_EQ(loadScene(json.string()).name, "furnace_0.5");
    const TempDir dir;
    const fs::path other = dir.write("scene.obj", "o cube\n");
    EXPECT_NE(errorOf([&] { loadScene(other.string()); }, other).find("unknown kind of file"),
              std::string::npos);
}

TEST(SceneFile, DdgiVolumesArePlacedAndBadOnesNamed) {
    const TempDir dir;
    const fs::path good = dir.write(
        "ddgi.json", sceneFile(", \"ddgiVolumes\": [{\"min\": [0, 0, 0], \"max\": [500, 500, 500], "
                               "\"probes\": [4, 2, 8]}, {\"min\": [-1, -1, -1], \"max\": [1, 1, 1]}]"));
    const Scene scene = loadScene(good.string());
    ASSERT_EQ(scene.probeVolumes.size(), 2u);
    EXPECT_EQ(scene.probeVolumes[0].counts, glm::uvec3(4, 2, 8));
    EXPECT_EQ(scene.probeVolumes[0].box.max, glm::vec3(500.0f));
    EXPECT_EQ(scene.probeVolumes[1].counts, glm::uvec3(16)); // the default
    for (const char* bad : {"[{\"min\": [0, 0, 0], \"max\": [0, 1, 1]}]",
                            "[{\"min\": [0, 0, 0], \"max\": [1, 1, 1], \"probes\": [1, 4, 4]}]",
                            "[{\"min\": [0, 0, 0], \"max\": [1, 1, 1], \"probes\": [4, 4]}]"}) {
        const fs::path file = dir.write("bad.json", sceneFile(std::string(", \"ddgiVolumes\": ") + bad));
        EXPECT_NE(errorOf([&] { loadScene(file.string()); }, file).find("ddgiVolumes[0]"), std::string::npos)
            << bad;
    }
}

TEST(SceneFile, DoorGapMovesTheDoorOffTheWall) {
    const TempDir dir;
    const auto doorMinX = [&](const std::string& json) {
        const Scene scene = loadScene(dir.write("door.json", json).string());
        float x = 1e9f;
        for (const Instance& instance : scene.instances) {
            if (instance.name == "door") {
                for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
                    x = std::min(x, glm::vec3(instance.transform * glm::vec4(p, 1.0f)).x);
                }
            }
        }
        return x;
    };
    const float shipped = doorMinX(R"({"generator": "door"})");
    EXPECT_NEAR(doorMinX(R"({"generator": "door", "doorGap": 0.01})"), shipped, 1e-6f);
    EXPECT_NEAR(doorMinX(R"({"generator": "door", "doorGap": 0.05})") - shipped, 0.04f, 1e-5f);
    EXPECT_NEAR(doorHinge(0.05f).x - doorHinge().x, 0.04f, 1e-6f);
}

} // namespace
} // namespace lumina::scene
