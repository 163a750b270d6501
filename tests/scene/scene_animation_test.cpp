// animateScene in memory: node hierarchies, looping clips, scripted paths (pivot, toggles, sun),
// untouched properties, and determinism (frame N is the same whatever was evaluated before).
#include "gi/scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

constexpr float kTolerance = 1e-5f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, const char* what) {
    EXPECT_NEAR(glm::length(actual - expected), 0.0f, kTolerance)
        << what << ": (" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

glm::vec3 place(const Instance& instance, const glm::vec3& p) {
    return glm::vec3(instance.transform * glm::vec4(p, 1.0f));
}

template <typename T>
Keyframes<T> track(std::vector<double> times, std::vector<T> values,
                   Interpolation interpolation = Interpolation::Linear) {
    return {interpolation, std::move(times), std::move(values)};
}

// Two instances and a light under an arm: the arm (root) slides along x over 2 s, its child
// (the hand, 1 unit up the arm) turns about y; instance 0 hangs from the hand, instance 1 and
// the light from the arm. 60 frames per second.
Scene armScene() {
    Scene scene;
    scene.instances = {{.name = "on hand"}, {.name = "on arm"}, {.name = "still"}};
    scene.lights = {{.type = LightType::Spot, .name = "lamp", .intensity = 5.0f}};
    SceneAnimation& a = scene.animation;
    a.nodes = {{.name = "arm"}, {.name = "hand", .parent = 0, .translation = {0.0, 1.0, 0.0}}};
    NodeClip clip{.name = "wave", .length = 2.0};
    clip.channels.push_back(
        {.node = 0,
         .property = NodeProperty::Translation,
         .vectorKeys = track<glm::vec3>({0.0, 2.0}, {glm::vec3(0.0f), glm::vec3(4.0f, 0.0f, 0.0f)})});
    clip.channels.push_back({.node = 1,
                             .property = NodeProperty::Rotation,
                             .rotationKeys = track<glm::quat>(
                                 {0.0, 1.0}, {glm::quat(1.0f, 0.0f, 0.0f, 0.0f),
                                              glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0))})});
    a.clips.push_back(clip);
    a.nodeInstances = {{.target = 0, .node = 1}, {.target = 1, .node = 0}};
    a.nodeLights = {{.target = 0, .node = 0}};
    return scene;
}

TEST(SceneAnimation, ParentsMoveTheirChildren) {
    Scene scene = armScene();
    ASSERT_FALSE(scene.animation.empty());
    animateScene(scene, 30); // 0.5 s: arm at x = 1, hand turned 45 degrees (slerp)
    expectNear(place(scene.instances[1], glm::vec3(0.0f)), {1.0f, 0.0f, 0.0f}, "arm origin");
    expectNear(place(scene.instances[0], glm::vec3(0.0f)), {1.0f, 1.0f, 0.0f}, "hand origin");
    const float c = std::cos(glm::radians(45.0f)), s = std::sin(glm::radians(45.0f));
    // (1, 0, 0) in the hand's frame, turned 45 degrees about +y: (cos, 0, -sin).
    expectNear(place(scene.instances[0], {1.0f, 0.0f, 0.0f}), {1.0f + c, 1.0f, -s}, "hand's x axis");
    expectNear(scene.lights[0].position, {1.0f, 0.0f, 0.0f}, "light under the arm");
    expectNear(scene.lights[0].direction, {0.0f, 0.0f, -1.0f}, "light direction (-z of its node)");
    // What no track drives stays as it was.
    EXPECT_EQ(scene.instances[2].transform, glm::mat4(1.0f));
    EXPECT_EQ(scene.lights[0].intensity, 5.0f);
}

TEST(SceneAnimation, ClipsLoopOverTheirLength) {
    Scene scene = armScene();
    animateScene(scene, 30);
    const glm::mat4 first = scene.instances[0].transform;
    animateScene(scene, 30 + 120); // one 2 s loop later
    for (int c = 0; c < 4; ++c) {
        expectNear(glm::vec3(scene.instances[0].transform[c]), glm::vec3(first[c]), "one loop later");
    }
    EXPECT_DOUBLE_EQ(scene.animation.length(), 2.0);
}

TEST(SceneAnimation, FrameNIsTheSameWhateverCameBefore) {
    Scene fresh = armScene();
    fresh.animation.instancePaths.push_back(
        {.instance = 2,
         .translation = track<glm::vec3>({0.0, 1.0}, {glm::vec3(0.0f), glm::vec3(0.0f, 3.0f, 0.0f)})});
    Scene replayed = fresh;
    animateScene(fresh, 77);
    for (const uint64_t frame : {5u, 200u, 76u, 0u, 1000u, 78u}) {
        animateScene(replayed, frame);
    }
    animateScene(replayed, 77);
    for (size_t i = 0; i < fresh.instances.size(); ++i) {
        EXPECT_EQ(fresh.instances[i].transform, replayed.instances[i].transform) << i;
    }
    EXPECT_EQ(fresh.lights[0].position, replayed.lights[0].position);
}

TEST(SceneAnimation, InstancePathsTurnAboutTheirPivotFromTheRestPose) {
    Scene scene;
    const glm::mat4 rest = glm::translate(glm::mat4(1.0f), {5.0f, 0.0f, 0.0f});
    scene.instances = {{.transform = rest, .name = "door"}};
    const glm::vec3 y(0.0f, 1.0f, 0.0f);
    scene.animation.instancePaths.push_back(
        {.instance = 0,
         .rest = rest,
         .pivot = {5.0f, 0.0f, 0.0f},
         .translation = track<glm::vec3>({0.0, 1.0}, {glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 2.0f)}),
         .rotation = track<glm::quat>({0.0, 1.0},
                                      {glm::angleAxis(0.0f, y), glm::angleAxis(glm::radians(90.0f), y)})});
    animateScene(scene, 60); // 1 s: turned 90 degrees about (5, y, 0), then moved 2 along z
    expectNear(place(scene.instances[0], glm::vec3(0.0f)), {5.0f, 0.0f, 2.0f}, "the pivot stays put");
    expectNear(place(scene.instances[0], {0.0f, 0.0f, 1.0f}), {6.0f, 0.0f, 2.0f}, "local +z turned to +x");
    animateScene(scene, 0);
    EXPECT_EQ(scene.instances[0].transform, rest);
}

TEST(SceneAnimation, TogglesSwitchLightsAndEmissionAtTheirFrame) {
    Scene scene;
    scene.framesPerSecond = 30.0f;
    scene.lights = {{.type = LightType::Point, .name = "bulb", .intensity = 8.0f}};
    scene.materials = {{.name = "lamp", .emission = {2.0f, 2.0f, 2.0f}}};
    const auto toggle =
        track<float>({0.0, 10.0 / 30.0, 20.0 / 30.0}, {1.0f, 0.0f, 1.0f}, Interpolation::Step);
    scene.animation.lightPaths.push_back({.light = 0, .restIntensity = 8.0f, .on = toggle});
    scene.animation.materialPaths.push_back(
        {.material = 0,
         .restEmission = {2.0f, 2.0f, 2.0f},
         .emission = track<glm::vec3>({0.0, 1.0}, {glm::vec3(2.0f), glm::vec3(4.0f)}),
         .on = toggle});
    animateScene(scene, 9);
    EXPECT_EQ(scene.lights[0].intensity, 8.0f);
    animateScene(scene, 10);
    EXPECT_EQ(scene.lights[0].intensity, 0.0f);
    EXPECT_EQ(scene.materials[0].emission, glm::vec3(0.0f));
    animateScene(scene, 20);
    EXPECT_EQ(scene.lights[0].intensity, 8.0f);
    expectNear(scene.materials[0].emission, glm::vec3(2.0f + 2.0f * 20.0f / 30.0f),
               "emission back on, keyed");
}

TEST(SceneAnimation, SunPathsGiveUnitDirections) {
    expectNear(sunDirection({0.0f, 90.0f}), {0.0f, -1.0f, 0.0f}, "noon at the zenith");
    expectNear(sunDirection({0.0f, 0.0f}), {0.0f, 0.0f, 1.0f}, "sun on the horizon at -z shines towards +z");
    expectNear(sunDirection({90.0f, 0.0f}), {-1.0f, 0.0f, 0.0f}, "sun at +x shines towards -x");
    Scene scene;
    scene.lights = {{.type = LightType::Directional, .name = "sun", .intensity = 3.0f}};
    scene.animation.scriptLoopSeconds = 2.0;
    scene.animation.lightPaths.push_back(
        {.light = 0,
         .sunDegrees = track<glm::vec2>({0.0, 2.0}, {glm::vec2(-90.0f, 10.0f), glm::vec2(90.0f, 10.0f)})});
    animateScene(scene, 60); // halfway: azimuth 0, elevation 10
    expectNear(scene.lights[0].direction, sunDirection({0.0f, 10.0f}), "halfway");
    EXPECT_NEAR(glm::length(scene.lights[0].direction), 1.0f, 1e-6f);
    animateScene(scene, 120 + 60); // looped
    expectNear(scene.lights[0].direction, sunDirection({0.0f, 10.0f}), "a loop later");
    EXPECT_EQ(scene.animation.animatedLights(), std::vector<uint32_t>{0});
    EXPECT_TRUE(scene.animation.animatedInstances().empty());
}

} // namespace
} // namespace lumina::scene
