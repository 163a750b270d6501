// Sky environments (gi/scene/sky_environment.h) and the default light (default_light.h):
// reading an EXR environment and every way one can be wrong; the direction convention of the
// CPU lookup; the scene file's "sky" object and LoadOptions; and the default-light rule (a scene
// without any light gets the sun and sky, built-in scenes with light are left alone).
#include "gi/image/exr.h"
#include "gi/scene/default_light.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_loader.h"
#include "gi/scene/sky_environment.h"
#include "tests/scene/test_files.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::scene {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// An RGB EXR of `width` x `height` whose texel (x, y) is value(x, y).
template <typename Value>
fs::path writeEnvironment(const TempDir& dir, const std::string& name, uint32_t width, uint32_t height,
                          Value value) {
    image::Image pixels = image::Image::rgb(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const glm::vec3 v = value(x, y);
            pixels.channel("R")[y * width + x] = v.r;
            pixels.channel("G")[y * width + x] = v.g;
            pixels.channel("B")[y * width + x] = v.b;
        }
    }
    const fs::path file = dir.path() / name;
    image::writeExr(file, pixels);
    return file;
}

std::string errorOf(const fs::path& file, float intensity = 1.0f) {
    try {
        readSkyEnvironment(file, intensity);
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), file);
        return error.what();
    }
    ADD_FAILURE() << "no SceneError for " << file;
    return {};
}

fs::path lightlessGltf(const TempDir& dir) {
    return dir.write("box.gltf", test::triangleGltf({0, 0, 0, 1, 0, 0, 0, 1, 0}).dump());
}

TEST(SkyEnvironment, ReadsTexelsTimesIntensity) {
    const TempDir dir;
    const fs::path file =
        writeEnvironment(dir, "sky.exr", 4, 2, [](uint32_t x, uint32_t y) { return glm::vec3(x, y, 1.0f); });
    const SkyEnvironment sky = readSkyEnvironment(file, 2.0f);
    EXPECT_EQ(sky.width, 4u);
    EXPECT_EQ(sky.height, 2u);
    EXPECT_EQ(sky.intensity, 2.0f);
    ASSERT_EQ(sky.radiance.size(), 8u);
    EXPECT_EQ(sky.radiance[1 * 4 + 3], glm::vec3(6.0f, 2.0f, 2.0f));
}

TEST(SkyEnvironment, BadInputIsAnErrorNamingTheProblem) {
    const TempDir dir;
    EXPECT_NE(errorOf(dir.path() / "missing.exr").find("no such file"), std::string::npos);
    EXPECT_NE(errorOf(dir.write("text.exr", std::string("not an image"))).find("not a readable RGB EXR"),
              std::string::npos);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const fs::path withNan = writeEnvironment(dir, "nan.exr", 3, 2, [&](uint32_t x, uint32_t y) {
        return x == 2 && y == 1 ? glm::vec3(0.0f, nan, 0.0f) : glm::vec3(1.0f);
    });
    EXPECT_NE(errorOf(withNan).find("texel (2, 1) channel G"), std::string::npos) << errorOf(withNan);
    const fs::path negative = writeEnvironment(
        dir, "negative.exr", 2, 1, [](uint32_t x, uint32_t) { return glm::vec3(x == 1 ? -0.5f : 0.5f); });
    EXPECT_NE(errorOf(negative).find("not negative"), std::string::npos) << errorOf(negative);
    const fs::path wide = writeEnvironment(dir, "wide.exr", kMaxSkyWidth + 1, 1,
                                           [](uint32_t, uint32_t) { return glm::vec3(1.0f); });
    EXPECT_NE(errorOf(wide).find("larger than"), std::string::npos) << errorOf(wide);
    const fs::path fine =
        writeEnvironment(dir, "fine.exr", 2, 1, [](uint32_t, uint32_t) { return glm::vec3(1e30f); });
    EXPECT_NE(errorOf(fine, -1.0f).find("intensity"), std::string::npos);
    EXPECT_NE(errorOf(fine, 1e20f).find("overflows"), std::string::npos);
}

// Row 0 is the zenith, the middle column looks along -z, longitude grows towards +x.
TEST(SkyEnvironment, DirectionConvention) {
    Scene scene;
    SkyEnvironment sky;
    sky.width = 4;
    sky.height = 2;
    // Columns: centres at longitudes -135, -45, 45, 135 degrees from -z towards +x.
    for (uint32_t y = 0; y < 2; ++y) {
        for (uint32_t x = 0; x < 4; ++x) {
            sky.radiance.push_back(glm::vec3(float(x), float(y), 0.0f));
        }
    }
    scene.skyEnvironment = sky;
    const glm::vec2 up = skyTexelCoordinates(sky, {0, 1, 0});
    EXPECT_FLOAT_EQ(up.y, 0.0f);
    const glm::vec2 front = skyTexelCoordinates(sky, {0, 0, -1});
    EXPECT_FLOAT_EQ(front.x, 2.0f);
    EXPECT_FLOAT_EQ(front.y, 1.0f);
    EXPECT_FLOAT_EQ(skyTexelCoordinates(sky, {1, 0, 0}).x, 3.0f);  // +x: a quarter turn on
    EXPECT_FLOAT_EQ(skyTexelCoordinates(sky, {-1, 0, 0}).x, 1.0f); // -x
    // Bilinear: at a texel centre, that texel; halfway, the mean; wrapping across +z.
    const float s = std::sqrt(0.5f);
    const glm::vec3 centre = skyRadiance(scene, glm::vec3(0.5f, s, -0.5f)); // column 2, row 0: its centre
    EXPECT_NEAR(centre.x, 2.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);
    const glm::vec3 back = skyRadiance(scene, glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f)));
    EXPECT_NEAR(back.x, 1.5f, 1e-5f) << "between column 3 and column 0 (wrapped)";
    scene.skyEnvironment.reset();
    scene.sky = {0.1f, 0.2f, 0.3f};
    EXPECT_EQ(skyRadiance(scene, {0, 1, 0}), scene.sky);
}

TEST(DefaultLight, AGltfWithoutLightGetsTheSunAndSky) {
    const TempDir dir;
    const fs::path gltf = lightlessGltf(dir);
    const Scene lit = loadScene(gltf.string());
    EXPECT_TRUE(lit.defaultLight);
    ASSERT_EQ(lit.lights.size(), 1u);
    EXPECT_EQ(lit.lights[0].type, LightType::Directional);
    EXPECT_EQ(lit.lights[0].intensity, kDefaultSunIrradiance);
    EXPECT_NEAR(-lit.lights[0].direction.y, std::sin(glm::radians(kDefaultSunElevationDegrees)), 1e-6f);
    EXPECT_EQ(lit.sky, kDefaultSky);
    EXPECT_TRUE(sceneHasLight(lit));

    const Scene dark = loadScene(gltf.string(), {.defaultLight = false});
    EXPECT_FALSE(dark.defaultLight);
    EXPECT_TRUE(dark.lights.empty());
    EXPECT_EQ(dark.sky, glm::vec3(0.0f));
    EXPECT_FALSE(sceneHasLight(dark));
}

TEST(DefaultLight, ScenesWithAnyLightAreLeftAlone) {
    for (const char* name : {"cornell_box", "cornell_box_point", "open_top_box", "furnace_0.5", "atrium"}) {
        SCOPED_TRACE(name);
        EXPECT_FALSE(loadScene(name).defaultLight);
    }
    // A sky alone is light: the --sky environment keeps the default light away.
    const TempDir dir;
    const fs::path sky =
        writeEnvironment(dir, "sky.exr", 2, 1, [](uint32_t, uint32_t) { return glm::vec3(0.5f); });
    const Scene underSky =
        loadScene(lightlessGltf(dir).string(), {.skyEnvironment = sky, .skyIntensity = 2.0f});
    EXPECT_FALSE(underSky.defaultLight);
    ASSERT_TRUE(underSky.skyEnvironment);
    EXPECT_EQ(underSky.skyEnvironment->radiance[0], glm::vec3(1.0f));
}

TEST(SceneFileSky, EnvironmentObjectAndArrayForms) {
    const TempDir dir;
    writeEnvironment(dir, "env.exr", 2, 1, [](uint32_t x, uint32_t) { return glm::vec3(float(x + 1)); });
    const std::string gltf = lightlessGltf(dir).generic_string();
    const fs::path object =
        dir.write("object.json", "{\"gltf\": \"" + gltf +
                                     "\", \"sky\": {\"environment\": \"env.exr\", \"intensity\": 0.5}}");
    const Scene a = loadScene(object.string());
    ASSERT_TRUE(a.skyEnvironment);
    EXPECT_EQ(a.skyEnvironment->file, dir.path() / "env.exr");
    EXPECT_EQ(a.skyEnvironment->radiance[1], glm::vec3(1.0f));
    EXPECT_FALSE(a.defaultLight);
    const fs::path array = dir.write("array.json", "{\"gltf\": \"" + gltf + "\", \"sky\": [0.1, 0.2, 0.3]}");
    const Scene b = loadScene(array.string());
    EXPECT_FALSE(b.skyEnvironment);
    EXPECT_EQ(b.sky, glm::vec3(0.1f, 0.2f, 0.3f));
    for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
             {"{\"environment\": \"missing.exr\"}", "no such file"},
             {"{\"intensity\": 2}", "'sky.environment' is required"},
             {"{\"environment\": \"env.exr\", \"intensity\": -1}", "'sky.intensity' must be"},
             {"{\"environment\": \"env.exr\", \"colour\": 1}", "unknown key 'sky.colour'"}}) {
        const fs::path file = dir.write("bad.json", "{\"gltf\": \"" + gltf + "\", \"sky\": " + text + "}");
        try {
            loadScene(file.string());
            ADD_FAILURE() << text << " accepted";
        } catch (const SceneError& error) {
            EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
        }
    }
}

} // namespace
} // namespace lumina::scene
