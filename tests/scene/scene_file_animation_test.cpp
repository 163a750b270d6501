// The scene file's "animation" section: keys by frame and by time, linear and step tracks, sun
// paths, unit conversion of light intensities, and every mistake an error naming the key.
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_loader.h"
#include "gi/scene/units.h"
#include "tests/scene/test_files.h"

#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

fs::path cornellGltf() {
    return test::sourceDir() / "scenes" / "cornell_box_point" / "cornell_box_point.gltf";
}

// The point-lit Cornell box (mm) with `extra` keys added at the top level.
std::string sceneFile(const std::string& extra) {
    return "{ \"gltf\": \"" + cornellGltf().generic_string() + "\", \"metresPerUnit\": 0.001" + extra + " }";
}

Scene load(const TempDir& dir, const std::string& extra) {
    return loadScene(dir.write("animated.json", sceneFile(extra)).string());
}

std::string errorOf(const TempDir& dir, const std::string& extra) {
    const fs::path file = dir.write("bad.json", sceneFile(extra));
    try {
        loadScene(file.string());
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), file);
        return error.what();
    }
    ADD_FAILURE() << "no SceneError for " << extra;
    return {};
}

TEST(SceneFileAnimation, ObjectLightAndMaterialPathsApply) {
    const TempDir dir;
    Scene scene = load(dir, R"(, "framesPerSecond": 30, "animation": {
        "objects": [{"instance": "short block", "keys": [
            {"frame": 0, "translation": [0, 0, 0]}, {"frame": 30, "translation": [90, 0, 0]}]}],
        "lights": [{"light": "light", "keys": [
            {"time": 0, "position": [278, 538.8, 279.6], "intensity": 0.05},
            {"time": 2, "position": [100, 538.8, 279.6], "intensity": 0.1}]}],
        "materials": [{"material": "white", "interpolation": "step", "keys": [
            {"frame": 0, "emission": [0, 0, 0]}, {"frame": 15, "emission": [1, 1, 1]}]}]})");
    EXPECT_EQ(scene.framesPerSecond, 30.0f);
    EXPECT_DOUBLE_EQ(scene.animation.length(), 2.0);
    const uint32_t block = scene.animation.instancePaths.at(0).instance;
    EXPECT_EQ(scene.instances[block].name, "short block");
    animateScene(scene, 10); // 1/3 s
    EXPECT_NEAR(scene.instances[block].transform[3].x, 30.0f, 1e-4f);
    const Light& light = scene.lights[0];
    EXPECT_NEAR(light.position.x, 278.0f - 178.0f / 6.0f, 1e-3f);
    // Candela to scene units (mm): I / 0.001^2, linear between 0.05 and 0.1 cd.
    EXPECT_NEAR(light.intensity, pointIntensityFromCandela(0.05 + 0.05 / 6.0, 0.001), 1e-2);
    EXPECT_EQ(scene.materials[0].emission, glm::vec3(0.0f));
    animateScene(scene, 15);
    EXPECT_EQ(scene.materials[0].emission, glm::vec3(1.0f));
    animateScene(scene, 1000); // no loop: the last keys hold
    EXPECT_NEAR(scene.instances[block].transform[3].x, 90.0f, 1e-4f);
    EXPECT_NEAR(scene.lights[0].position.x, 100.0f, 1e-3f);
}

TEST(SceneFileAnimation, TheLoadedSceneIsFrameZero) {
    const TempDir dir;
    const Scene scene = load(dir, R"(, "animation": {"objects": [{"instance": "short block", "keys": [
        {"frame": 0, "translation": [0, 10, 0]}, {"frame": 60, "translation": [0, 20, 0]}]}]})");
    EXPECT_NEAR(scene.instances[scene.animation.instancePaths[0].instance].transform[3].y, 10.0f, 1e-5f);
    // The path starts from the file's pose, not from frame 0's.
    EXPECT_EQ(scene.animation.instancePaths[0].rest, glm::mat4(1.0f));
}

TEST(SceneFileAnimation, TogglesAndLoops) {
    const TempDir dir;
    Scene scene = load(dir, R"(, "animation": {"loopFrames": 100, "lights": [{"light": "light", "keys": [
        {"frame": 0, "on": true}, {"frame": 40, "on": false}, {"frame": 41, "on": true}]}]})");
    const float on = scene.lights[0].intensity;
    EXPECT_GT(on, 0.0f);
    animateScene(scene, 40);
    EXPECT_EQ(scene.lights[0].intensity, 0.0f);
    animateScene(scene, 41);
    EXPECT_EQ(scene.lights[0].intensity, on);
    animateScene(scene, 140); // the loop's frame 40
    EXPECT_EQ(scene.lights[0].intensity, 0.0f);
    EXPECT_DOUBLE_EQ(scene.animation.length(), 100.0 / 60.0);
}

TEST(SceneFileAnimation, MistakesAreErrorsNamingTheKey) {
    const TempDir dir;
    const struct {
        const char* extra;
        const char* expected;
    } cases[] = {
        {R"(, "framesPerSecond": 0)", "'framesPerSecond' must be in [1, 10000]"},
        {R"(, "animation": {})", "animates nothing"},
        {R"(, "animation": {"objects": [{"keys": [{"frame": 0, "translation": [0,0,0]}]}]})",
         "'animation.objects[0].instance' is required"},
        {R"(, "animation": {"objects": [{"instance": "short block"}]})",
         "'animation.objects[0].keys' is required"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": []}]})",
         "'animation.objects[0].keys' is required"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"translation": [0,0,0]}]}]})",
         "'animation.objects[0].keys[0].frame' or 'time'"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 1, "time": 1, "translation": [0,0,0]}]}]})",
         "exactly one of them"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 5, "translation": [0,0,0]}, {"frame": 5, "translation": [1,0,0]}]}]})",
         "'animation.objects[0].keys[1].frame' must be later than the previous key's"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": -1, "translation": [0,0,0]}]}]})",
         "'animation.objects[0].keys[0].frame' must be a whole number"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"time": -1, "translation": [0,0,0]}]}]})",
         "'animation.objects[0].keys[0].time' must be in"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 0, "translation": [0,0]}]}]})",
         "'animation.objects[0].keys[0].translation' must be an array of three"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 0, "rotation": {"axis": [0,0,0], "degrees": 5}}]}]})",
         "'animation.objects[0].keys[0].rotation.axis' must not be a zero vector"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 0, "rotation": {"degrees": 5}}]}]})",
         "'animation.objects[0].keys[0].rotation.axis' is required"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 0, "translation": [1e30, 0, 0]}]}]})",
         "'animation.objects[0].keys[0].translation' must be within 1e8"},
        {R"(, "animation": {"objects": [{"instance": "short block", "keys": [{"frame": 0}]}]})",
         "set neither 'translation' nor 'rotation'"},
        {R"(, "animation": {"objects": [{"instance": "short block", "interpolation": "cubic", "keys": [{"frame": 0, "translation": [0,0,0]}]}]})",
         "'animation.objects[0].interpolation' must be linear or step"},
        {R"(, "animation": {"objects": [{"instance": "round block", "keys": [{"frame": 0, "translation": [0,0,0]}]}]})",
         "names instance 'round block', but the scene has none of that name (instances: 'floor'"},
        {R"(, "animation": {"objects": [{"instance": "floor", "keys": [{"frame": 0, "translation": [0,0,0]}]},
                                         {"instance": "floor", "keys": [{"frame": 0, "translation": [0,0,0]}]}]})",
         "'animation.objects[1].instance' names instance 'floor', which another path"},
        {R"(, "animation": {"lights": [{"light": "sun", "keys": [{"frame": 0, "on": false}]}]})",
         "'animation.lights[0].light' names light 'sun', but the scene has none"},
        {R"(, "animation": {"sun": {"keys": [{"frame": 0, "azimuthDegrees": 0, "elevationDegrees": 10}]}})",
         "'animation.sun.light' names light 'sun'"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "direction": [0,-1,0]}]}]})",
         "turns point light 'light', which has no direction"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "intensity": -1}]}]})",
         "'animation.lights[0].keys[0].intensity' must not be negative"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "color": [1, -1, 0]}]}]})",
         "'animation.lights[0].keys[0].color' must not be negative"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "on": 1}]}]})",
         "'animation.lights[0].keys[0].on' must be true or false"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "azimuthDegrees": 10}]}]})",
         "'animation.lights[0].keys[0].elevationDegrees' is required with the other"},
        {R"(, "animation": {"lights": [{"light": "light", "keys": [{"frame": 0, "colour": [1, 1, 1]}]}]})",
         "unknown key 'animation.lights[0].keys[0].colour'"},
        {R"(, "animation": {"materials": [{"material": "chrome", "keys": [{"frame": 0, "on": false}]}]})",
         "names material 'chrome', but the scene has none"},
        {R"(, "animation": {"materials": [{"material": "white", "keys": [{"frame": 0, "emission": [1, 1, NaN]}]}]})",
         "malformed JSON"},
        {R"(, "animation": {"loopFrames": 0, "materials": [{"material": "white", "keys": [{"frame": 0, "on": false}]}]})",
         "'animation.loopFrames' must be a whole number"},
        {R"(, "animation": {"loopFrames": 5, "loopSeconds": 1, "materials": [{"material": "white", "keys": [{"frame": 0, "on": false}]}]})",
         "cannot both be given"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.extra);
        const std::string message = errorOf(dir, c.extra);
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    }
}

TEST(SceneFileAnimation, SunPathsNeedADirectionalLight) {
    const TempDir dir;
    const fs::path file = dir.write("sunny.json", R"({"generator": "atrium", "animation": {"sun": {"keys": [
        {"frame": 0, "azimuthDegrees": -90, "elevationDegrees": 0},
        {"frame": 60, "azimuthDegrees": 90, "elevationDegrees": 0}]}}})");
    Scene scene = loadScene(file.string());
    animateScene(scene, 30);
    EXPECT_NEAR(scene.lights[0].direction.y, 0.0f, 1e-6f);
    EXPECT_NEAR(scene.lights[0].direction.z, 1.0f, 1e-6f); // the sun at -z at noon, shining +z
}

} // namespace
} // namespace lumina::scene
