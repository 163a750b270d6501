// A Lambertian plane seen from above under one light, built in code: the plane cannot see
// itself, so every pixel that sees it has the closed-form radiance rho / pi * E, where E is
// the light's irradiance by the conventions of shaders/common/lights_shared.h (I cos / d^2
// for a point light, with KHR_lights_punctual's spot cone and range window; the stated
// irradiance times cos for a directional light), or rho * S under a uniform sky S. Pixel
// centres are sampled (no jitter), so each pixel's value is exact up to rounding.
#include "gi/core/camera.h"
#include "tests/pathtracer/path_tracer_fixture.h"
#include "tests/scene/sky_test_scenes.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <optional>

namespace lumina::test {
namespace {

using AnalyticLightTest = PathTracerTest;

constexpr uint32_t kSize = 32;
constexpr float kHalfSide = 1.0f; // the plane spans [-1, 1] in x and z at y = 0 (makeFloorScene)
const glm::vec3 kAlbedo(0.8f, 0.5f, 0.2f);
// Pixels whose centre ray lands this close to the plane's edge are skipped (rounding).
constexpr float kEdgeMargin = 1e-3f;
constexpr float kRelativeTolerance = 1e-4f;
constexpr float kAbsoluteTolerance = 1e-6f;

// The plane (front face +y), camera 2.5 units above looking down, black sky.
scene::Scene makePlaneScene(const glm::mat4& transform = glm::mat4(1.0f)) {
    scene::Scene scene = makeFloorScene(kSize, kAlbedo);
    scene.name = "analytic plane";
    scene.instances[0].transform = transform;
    return scene;
}

// Where the centre ray of pixel (x, y) meets the plane y = 0, through the shared camera model.
std::optional<glm::vec3> planeHit(const scene::Scene& scene, uint32_t x, uint32_t y) {
    const gpu::GpuCamera camera = gi::makeGpuCamera(scene.camera, scene.image.width, scene.image.height);
    const glm::vec3 origin = gpu::cameraPosition(camera);
    const glm::vec3 direction = gpu::cameraRayDirection(camera, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
    const float t = -origin.y / direction.y;
    const glm::vec3 p = origin + t * direction;
    if (std::abs(p.x) > kHalfSide + kEdgeMargin || std::abs(p.z) > kHalfSide + kEdgeMargin) {
        return glm::vec3(INFINITY); // misses: sky
    }
    if (std::abs(p.x) > kHalfSide - kEdgeMargin || std::abs(p.z) > kHalfSide - kEdgeMargin) {
        return std::nullopt; // too close to the edge to call
    }
    return p;
}

// Renders `scene` at pixel centres and compares every pixel with expected(p) (p on the plane)
// or `skyValue` where the ray misses.
template <typename Expected>
void expectImage(AnalyticLightTest& test, const scene::Scene& scene, Expected expected, glm::vec3 skyValue,
                 uint32_t spp = 1) {
    gi::PathTracerSettings settings;
    settings.jitter = false;
    const gi::PathTracerResult result = test.render(scene, settings, spp);
    uint32_t compared = 0, onPlane = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> p = planeHit(scene, x, y);
            if (!p) {
                continue;
            }
            const bool miss = std::isinf(p->x);
            const glm::vec3 want = miss ? skyValue : expected(*p);
            const image::Rgb got = result.image.rgbAt(x, y);
            const float values[3] = {got.r, got.g, got.b};
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(values[c], want[c], kAbsoluteTolerance + kRelativeTolerance * want[c])
                    << "pixel (" << x << ", " << y << ") channel " << c << (miss ? " (sky)" : " (plane)");
            }
            ++compared;
            onPlane += miss ? 0 : 1;
        }
    }
    EXPECT_GT(onPlane, kSize * kSize / 3) << "the plane should fill much of the image";
    EXPECT_GT(compared - onPlane, 0u) << "some pixels should see the sky";
}

glm::vec3 lambert(glm::vec3 irradiance) {
    return kAlbedo * irradiance * std::numbers::inv_pi_v<float>;
}

TEST_P(AnalyticLightTest, PointLightGivesIntensityCosOverDistanceSquared) {
    scene::Scene scene = makePlaneScene();
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = {0.3f, 1.5f, -0.2f};
    light.color = {1.0f, 0.5f, 0.25f};
    light.intensity = 2.0f;
    scene.lights.push_back(light);
    expectImage(
        *this, scene,
        [&](glm::vec3 p) {
            const glm::vec3 toLight = light.position - p;
            const float d2 = glm::dot(toLight, toLight);
            const float cosTheta = toLight.y / std::sqrt(d2);
            return lambert(light.strength() * cosTheta / d2);
        },
        glm::vec3(0.0f));
}

TEST_P(AnalyticLightTest, SpotLightFollowsKhrConeAndRangeFalloff) {
    scene::Scene scene = makePlaneScene();
    scene::Light light;
    light.type = scene::LightType::Spot;
    light.position = {-0.2f, 1.2f, 0.1f};
    light.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.0f));
    light.innerConeAngle = glm::radians(15.0f);
    light.outerConeAngle = glm::radians(35.0f);
    light.range = 2.0f;
    light.intensity = 3.0f;
    scene.lights.push_back(light);
    expectImage(
        *this, scene,
        [&](glm::vec3 p) {
            // Written out from KHR_lights_punctual, independently of lights_shared.h.
            const glm::vec3 toLight = light.position - p;
            const float d = glm::length(toLight);
            const float cosTheta = toLight.y / d;
            const float cosAxis = glm::dot(-toLight / d, light.direction);
            const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
            const float t = std::clamp((cosAxis - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
            const float window = std::clamp(1.0f - std::pow(d / light.range, 4.0f), 0.0f, 1.0f);
            return lambert(light.strength() * (t * t * window * cosTheta / (d * d)));
        },
        glm::vec3(0.0f));
}

TEST_P(AnalyticLightTest, DirectionalLightGivesIrradianceTimesCos) {
    scene::Scene scene = makePlaneScene();
    scene::Light light;
    light.type = scene::LightType::Directional;
    light.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f)); // where the light travels
    light.color = {0.9f, 1.0f, 0.7f};
    light.intensity = 4.0f;
    scene.lights.push_back(light);
    const float cosTheta = -light.direction.y;
    expectImage(
        *this, scene, [&](glm::vec3) { return lambert(light.strength() * cosTheta); }, glm::vec3(0.0f));
}

// Under a uniform sky S the plane receives pi S and leaves rho S; every cosine-weighted
// sample carries exactly that, so a few samples are exact too.
TEST_P(AnalyticLightTest, UniformSkyGivesAlbedoTimesSky) {
    scene::Scene scene = makePlaneScene();
    scene.sky = {0.3f, 0.6f, 1.2f};
    expectImage(
        *this, scene, [&](glm::vec3) { return kAlbedo * scene.sky; }, scene.sky, 4);
}

// A base-colour texture (sRGB, decoded by the sampler) multiplies the albedo: under a uniform
// sky each pixel inside a texel block is baseColor x texel x S. Four blocks of different
// colours also pin the texture's orientation (uv (0, 0) is the image's top-left texel).
TEST_P(AnalyticLightTest, BaseColourTextureScalesTheAlbedo) {
    scene::Scene scene = makePlaneScene();
    scene.sky = glm::vec3(1.0f, 0.8f, 0.6f);
    constexpr uint32_t kTexels = 8;
    const uint8_t blocks[2][2][3] = {{{255, 0, 0}, {0, 255, 0}}, {{0, 0, 255}, {128, 200, 40}}};
    scene::Texture texture;
    texture.name = "quadrants";
    texture.width = texture.height = kTexels;
    for (uint32_t y = 0; y < kTexels; ++y) {
        for (uint32_t x = 0; x < kTexels; ++x) {
            const uint8_t* c = blocks[y * 2 / kTexels][x * 2 / kTexels];
            texture.rgba8.insert(texture.rgba8.end(), {c[0], c[1], c[2], 255});
        }
    }
    scene.textures.push_back(texture);
    scene.materials[0].baseColorTexture = 0;
    // The 8-bit sRGB decode of a GPU sampler may be approximate (Vulkan allows it; lavapipe's
    // is 1% off for dark values), while the quadrants differ by far more than this.
    constexpr float kTextureTolerance = 0.02f;
    auto srgbDecode = [](uint8_t v) {
        const float c = v / 255.0f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    gi::PathTracerSettings settings;
    settings.jitter = false;
    const gi::PathTracerResult result = render(scene, settings, 2);
    uint32_t checked = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> p = planeHit(scene, x, y);
            if (!p || std::isinf(p->x)) {
                continue;
            }
            // uv = ((x + 1) / 2, (z + 1) / 2) on this plane; skip a texel around the block edges,
            // where bilinear filtering blends the blocks (and the wrap at the plane's border).
            const glm::vec2 uv((p->x + 1.0f) * 0.5f, (p->z + 1.0f) * 0.5f);
            const glm::vec2 texel = uv * float(kTexels);
            const glm::vec2 inBlock = glm::mod(texel, float(kTexels / 2));
            if (glm::any(glm::lessThan(inBlock, glm::vec2(1.0f))) ||
                glm::any(glm::greaterThan(inBlock, glm::vec2(kTexels / 2 - 1.0f)))) {
                continue;
            }
            const uint8_t* c = blocks[int(uv.y * 2.0f)][int(uv.x * 2.0f)];
            const glm::vec3 want =
                kAlbedo * glm::vec3(srgbDecode(c[0]), srgbDecode(c[1]), srgbDecode(c[2])) * scene.sky;
            const image::Rgb got = result.image.rgbAt(x, y);
            EXPECT_NEAR(got.r, want.r, kTextureTolerance * want.r + 1e-6f)
                << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(got.g, want.g, kTextureTolerance * want.g + 1e-6f)
                << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(got.b, want.b, kTextureTolerance * want.b + 1e-6f)
                << "pixel (" << x << ", " << y << ")";
            ++checked;
        }
    }
    EXPECT_GT(checked, 40u);
}

// Emission leaves the front face only: seen from above, a plane whose front faces up shows
// Le; mirrored by its instance (x -> -x, which reverses the winding in world space) its front
// still faces up; turned upside down, it shows nothing.
TEST_P(AnalyticLightTest, EmissionLeavesTheFrontFaceOnly) {
    const glm::vec3 le(2.0f, 1.0f, 0.5f);
    auto emissive = [&](const glm::mat4& transform) {
        scene::Scene scene = makePlaneScene(transform);
        scene.materials[0].emission = le;
        scene.materials[0].baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        return scene;
    };
    {
        SCOPED_TRACE("front face up");
        expectImage(
            *this, emissive(glm::mat4(1.0f)), [&](glm::vec3) { return le; }, glm::vec3(0.0f));
    }
    {
        SCOPED_TRACE("mirrored instance");
        expectImage(
            *this, emissive(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f))),
            [&](glm::vec3) { return le; }, glm::vec3(0.0f));
    }
    {
        SCOPED_TRACE("front face down");
        expectImage(
            *this, emissive(glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float>, glm::vec3(1, 0, 0))),
            [&](glm::vec3) { return glm::vec3(0.0f); }, glm::vec3(0.0f));
    }
}

LUMINA_INSTANTIATE_GPU_TEST(AnalyticLightTest);

} // namespace
} // namespace lumina::test
