// glTF animations through the real loader: a small glTF written here, with a node hierarchy,
// LINEAR, STEP and CUBICSPLINE samplers and two looping animations; then each kind of malformed
// animation data, which must be a SceneError naming the problem.
#include "gi/scene/animation_summary.h"
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_loader.h"
#include "tests/scene/test_files.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::scene {
namespace {

using Json = nlohmann::json;

// The float arrays the animations read, each its own bufferView and accessor (after the mesh's
// positions, accessor 0).
struct AnimationData {
    std::vector<float> slideTimes{0.0f, 2.0f};                                 // accessor 1
    std::vector<float> slideValues{0, 0, 0, 4, 0, 0};                          // accessor 2, VEC3
    std::vector<float> stepTimes{0.0f, 1.0f};                                  // accessor 3
    std::vector<float> turnValues{0, 0, 0, 1, 0, 0.70710678f, 0, 0.70710678f}; // accessor 4, VEC4
    // accessor 5, VEC3 x 6: in-tangent, value, out-tangent per key; zero tangents.
    std::vector<float> growValues{0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 3, 3, 3, 0, 0, 0};
};

// Nodes: 0 "arm" (slides along x over 2 s, LINEAR) with child 1 "hand" (1 up, turns 90 degrees
// about y at 1 s, STEP); 2 "still"; 3 "grow" (scale 1 to 3 over 1 s, CUBICSPLINE, its own
// animation). Every node draws the unit quad.
Json animatedGltf(const AnimationData& data = {}) {
    const std::vector<float> quad = test::unitQuad();
    std::vector<std::vector<float>> arrays = {quad,           data.slideTimes, data.slideValues,
                                              data.stepTimes, data.turnValues, data.growValues};
    const char* types[] = {"VEC3", "SCALAR", "VEC3", "SCALAR", "VEC4", "VEC3"};
    const size_t components[] = {3, 1, 3, 1, 4, 3};
    std::vector<uint8_t> bytes;
    Json accessors = Json::array(), views = Json::array();
    for (size_t i = 0; i < arrays.size(); ++i) {
        const size_t offset = bytes.size();
        bytes.resize(offset + arrays[i].size() * 4);
        std::memcpy(bytes.data() + offset, arrays[i].data(), arrays[i].size() * 4);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", arrays[i].size() * 4}});
        accessors.push_back({{"bufferView", i},
                             {"componentType", 5126},
                             {"count", arrays[i].size() / components[i]},
                             {"type", types[i]}});
    }
    Json doc = test::triangleGltf(quad);
    doc["accessors"] = accessors;
    doc["bufferViews"] = views;
    doc["buffers"] = Json::array({{{"byteLength", bytes.size()},
                                   {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}});
    doc["nodes"] = Json::array({{{"name", "arm"}, {"mesh", 0}, {"children", {1}}},
                                {{"name", "hand"}, {"mesh", 0}, {"translation", {0, 1, 0}}},
                                {{"name", "still"}, {"mesh", 0}, {"translation", {0, 0, 5}}},
                                {{"name", "grow"}, {"mesh", 0}, {"translation", {0, 0, -5}}}});
    doc["scenes"] = Json::array({{{"nodes", {0, 2, 3}}}});
    doc["animations"] = Json::array(
        {{{"name", "wave"},
          {"samplers",
           {{{"input", 1}, {"output", 2}}, {{"input", 3}, {"output", 4}, {"interpolation", "STEP"}}}},
          {"channels",
           {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
            {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}}}}},
         {{"name", "grow"},
          {"samplers", {{{"input", 3}, {"output", 5}, {"interpolation", "CUBICSPLINE"}}}},
          {"channels", {{{"sampler", 0}, {"target", {{"node", 3}, {"path", "scale"}}}}}}}});
    return doc;
}

Scene loadText(const Json& doc) {
    const std::string text = doc.dump();
    return loadGltfMemory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, false,
                          "animated.gltf", ".");
}

const Instance& named(const Scene& scene, const std::string& name) {
    for (const Instance& instance : scene.instances) {
        if (instance.name == name) {
            return instance;
        }
    }
    ADD_FAILURE() << "no instance " << name;
    return scene.instances.front();
}

glm::vec3 at(const Instance& instance, const glm::vec3& p) {
    return glm::vec3(instance.transform * glm::vec4(p, 1.0f));
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, const std::string& what) {
    EXPECT_NEAR(glm::length(actual - expected), 0.0f, 1e-5f)
        << what << ": (" << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

TEST(GltfAnimation, ChannelsDriveInstancesThroughTheHierarchy) {
    Scene scene = loadText(animatedGltf());
    EXPECT_TRUE(scene.report.warnings.empty());
    ASSERT_EQ(scene.animation.clips.size(), 2u);
    EXPECT_EQ(scene.animation.clips[0].name, "wave");
    EXPECT_DOUBLE_EQ(scene.animation.clips[0].length, 2.0);
    EXPECT_DOUBLE_EQ(scene.animation.length(), 2.0);
    EXPECT_EQ(scene.animation.animatedInstances().size(), 3u); // arm, hand, grow; not still

    animateScene(scene, 30); // 0.5 s: arm at x = 1; the hand not yet turned (STEP)
    expectNear(at(named(scene, "arm"), glm::vec3(0.0f)), {1.0f, 0.0f, 0.0f}, "arm");
    expectNear(at(named(scene, "hand"), {1.0f, 0.0f, 0.0f}), {2.0f, 1.0f, 0.0f}, "hand before its step");
    // Cubic with zero tangents at u = 0.5: 1 + (3 - 1)(3u^2 - 2u^3) = 2.
    expectNear(at(named(scene, "grow"), {1.0f, 0.0f, 0.0f}), {2.0f, 0.0f, -5.0f}, "grow at 0.5 s");
    expectNear(at(named(scene, "still"), glm::vec3(0.0f)), {0.0f, 0.0f, 5.0f}, "still");

    animateScene(scene, 60); // 1 s: arm at x = 2, the hand turned 90 degrees about y
    expectNear(at(named(scene, "hand"), {1.0f, 0.0f, 0.0f}), {2.0f, 1.0f, -1.0f}, "hand after its step");
    // "grow" is 1 s long: at 1 s it has looped back to its start.
    expectNear(at(named(scene, "grow"), {1.0f, 0.0f, 0.0f}), {1.0f, 0.0f, -5.0f}, "grow looped");

    animateScene(scene, 150); // 2.5 s: "wave" looped to 0.5 s
    expectNear(at(named(scene, "arm"), glm::vec3(0.0f)), {1.0f, 0.0f, 0.0f}, "arm a loop later");
}

TEST(GltfAnimation, LightsFollowTheirNodes) {
    Json doc = animatedGltf();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual",
                          {{"lights", {{{"type", "spot"}, {"intensity", 2.0}, {"spot", Json::object()}}}}}}};
    doc["nodes"][1]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
    Scene scene = loadText(doc);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.animation.animatedLights(), std::vector<uint32_t>{0});
    animateScene(scene, 30); // on the hand: (1, 1, 0), still looking along -z
    expectNear(scene.lights[0].position, {1.0f, 1.0f, 0.0f}, "light position");
    expectNear(scene.lights[0].direction, {0.0f, 0.0f, -1.0f}, "light direction");
    animateScene(scene, 60); // the hand turned 90 degrees about y: -z becomes -x
    expectNear(scene.lights[0].position, {2.0f, 1.0f, 0.0f}, "light position at 1 s");
    expectNear(scene.lights[0].direction, {-1.0f, 0.0f, 0.0f}, "light direction at 1 s");
    EXPECT_EQ(scene.lights[0].intensity, 2.0f); // no track: untouched
}

// A scene file that replaces the glTF's lights drops their animation with them: the light that
// takes the animated one's index stays where the file put it.
TEST(GltfAnimation, ReplacedLightsLoseTheirAnimation) {
    Json doc = animatedGltf();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 2.0}}}}}}};
    doc["nodes"][1]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
    const test::TempDir dir;
    dir.write("animated.gltf", doc.dump());
    const auto file = dir.write("replaced.json", R"({"gltf": "animated.gltf", "replaceLights": true,
        "lights": [{"type": "point", "name": "fixed", "position": [0, 7, 0], "intensity": 1}]})");
    Scene scene = loadScene(file.string());
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.animation.animatedLights().empty());
    EXPECT_EQ(scene.animation.animatedInstances().size(), 3u); // the instances still move
    animateScene(scene, 30);
    expectNear(scene.lights[0].position, {0.0f, 7.0f, 0.0f}, "the scene file's light");
}

TEST(GltfAnimation, SummaryNamesNodesAndInterpolation) {
    const std::vector<std::string> lines = animationSummary(loadText(animatedGltf()));
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(
        lines[0],
        "3 tracks on 3 instances, 0 lights, 0 materials; loops every 2 s (120 frames at 60 per second)");
    EXPECT_EQ(lines[1],
              "glTF animation 'wave', 2 s: node 'arm' translation (2 keys, linear), node 'hand' rotation "
              "(2 keys, step)");
    EXPECT_EQ(lines[2], "glTF animation 'grow', 1 s: node 'grow' scale (2 keys, cubicspline)");
}

TEST(GltfAnimation, TheLoadedSceneIsFrameZero) {
    AnimationData data;
    data.slideValues = {7, 0, 0, 4, 0, 0}; // the animation starts away from the node's rest pose
    const Scene scene = loadText(animatedGltf(data));
    expectNear(at(named(scene, "arm"), glm::vec3(0.0f)), {7.0f, 0.0f, 0.0f}, "arm at frame 0");
}

TEST(GltfAnimation, MorphWeightsAreIgnoredWithAWarning) {
    Json doc = animatedGltf();
    doc["animations"][1]["channels"][0]["target"]["path"] = "weights";
    const Scene scene = loadText(doc);
    ASSERT_EQ(scene.report.warnings.size(), 1u);
    EXPECT_NE(scene.report.warnings[0].find("morph target weights"), std::string::npos);
    EXPECT_EQ(scene.animation.clips.size(), 1u);
}

TEST(GltfAnimation, MalformedAnimationsAreErrors) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* what;
        Json doc;
        const char* expected;
    };
    std::vector<Case> cases;
    auto edit = [&](const char* what, auto&& change, const char* expected) {
        Json doc = animatedGltf();
        change(doc);
        cases.push_back({what, doc, expected});
    };
    auto data = [&](const char* what, auto&& change, const char* expected) {
        AnimationData d;
        change(d);
        cases.push_back({what, animatedGltf(d), expected});
    };
    edit(
        "missing node", [](Json& d) { d["animations"][0]["channels"][0]["target"]["node"] = 99; },
        "animation 0 'wave' channel 0: target node 99 does not exist");
    edit(
        "missing sampler", [](Json& d) { d["animations"][0]["channels"][1]["sampler"] = 5; },
        "channel 1: sampler 5 does not exist");
    edit(
        "input not scalar", [](Json& d) { d["animations"][0]["samplers"][0]["input"] = 2; },
        "channel 0 input: accessor 2 should be SCALAR");
    edit(
        "rotation output not VEC4", [](Json& d) { d["animations"][0]["samplers"][1]["output"] = 2; },
        "channel 1 output: accessor 2 should be VEC4");
    edit(
        "input not float",
        [](Json& d) {
            d["accessors"][1]["componentType"] = 5123;
            d["accessors"][1]["normalized"] = true;
        },
        "must hold floats");
    edit(
        "unknown interpolation",
        [](Json& d) { d["animations"][0]["samplers"][0]["interpolation"] = "BEZIER"; },
        "unknown interpolation 'BEZIER'");
    edit(
        "unknown path", [](Json& d) { d["animations"][0]["channels"][0]["target"]["path"] = "colour"; },
        "unknown target path 'colour'");
    edit(
        "matrix node",
        [](Json& d) { d["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; },
        "has a matrix");
    edit(
        "two channels on one property",
        [](Json& d) {
            d["animations"][0]["channels"][1]["target"] = {{"node", 0}, {"path", "translation"}};
        },
        "a second channel for the translation of node 0");
    edit(
        "cubic output count",
        [](Json& d) { d["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE"; },
        "has 2 values, not the 6 its keys need");
    data(
        "times not increasing",
        [](AnimationData& d) {
            d.slideTimes = {2.0f, 1.0f};
        },
        "key times are not increasing (key 1 at 1");
    data(
        "equal times",
        [](AnimationData& d) {
            d.stepTimes = {1.0f, 1.0f};
        },
        "key times are not increasing");
    data(
        "negative time",
        [](AnimationData& d) {
            d.slideTimes = {-1.0f, 1.0f};
        },
        "key 0 time is -1");
    data(
        "NaN time",
        [&](AnimationData& d) {
            d.slideTimes = {0.0f, nan};
        },
        "key 1 time is nan");
    data(
        "NaN value", [&](AnimationData& d) { d.slideValues[4] = nan; },
        "channel 0 output: value 1 is not finite");
    data(
        "huge value", [&](AnimationData& d) { d.slideValues[3] = 1e30f; }, "value 1 holds");
    data(
        "zero quaternion", [](AnimationData& d) { d.turnValues = {0, 0, 0, 1, 0, 0, 0, 0}; },
        "key 1 is a zero-length quaternion");
    data(
        "too few values",
        [](AnimationData& d) {
            d.slideValues = {0, 0, 0};
        },
        "has 1 values, not the 2");
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        try {
            loadText(c.doc);
            ADD_FAILURE() << "loaded";
        } catch (const SceneError& error) {
            EXPECT_NE(std::string(error.what()).find(c.expected), std::string::npos) << error.what();
        }
    }
}

} // namespace
} // namespace lumina::scene
