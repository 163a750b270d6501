// The path tracer under an environment sky (shaders/pathtracer/path_trace.hlsl reads
// common/sky_sampling.hlsli on every miss):
//   - camera rays that miss see the environment along their direction, texel for texel as the
//     CPU lookup (gi/scene/sky_environment.h) computes it: the GPU and CPU conventions agree;
//   - a floor under a sky bright above and dark below leaves rho x the upper radiance, and
//     nothing under the reverse: light arrives from the direction the texel says.
#include "gi/core/camera.h"
#include "gi/scene/sky_environment.h"
#include "tests/pathtracer/path_tracer_fixture.h"
#include "tests/scene/sky_test_scenes.h"

#include <cmath>

namespace lumina::test {
namespace {

using EnvironmentSkyTest = PathTracerTest;

constexpr uint32_t kSize = 32;

// A different colour in every texel, smooth enough that bilinear lookups differ from nearest
// ones: a hue wheel in longitude, darker towards the nadir.
scene::SkyEnvironment hueWheel(uint32_t width, uint32_t height) {
    return makeEnvironment("hue wheel", width, height, [&](uint32_t x, uint32_t y) {
        const float a = 6.2831853f * float(x) / float(width);
        const float fade = 1.0f - 0.8f * float(y) / float(height);
        return fade * glm::vec3(1.0f + std::cos(a), 1.0f + std::cos(a - 2.094f), 1.0f + std::cos(a + 2.094f));
    });
}

TEST_P(EnvironmentSkyTest, CameraRaysThatMissSeeTheEnvironmentAlongTheirDirection) {
    scene::Scene scene = makeFloorScene(kSize);
    scene.skyEnvironment = hueWheel(16, 8);
    // Looking out sideways and a little up, with a wide view: most rays miss the floor below.
    scene.camera.position = {0.0f, 0.5f, 0.0f};
    scene.camera.forward = glm::normalize(glm::vec3(1.0f, 0.3f, -0.4f));
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0, 1, 0)), scene.camera.forward));
    scene.camera.fovY = glm::radians(100.0f);
    gi::PathTracerSettings settings;
    settings.jitter = false;
    settings.maxBounces = 0; // emission and sky only
    const gi::PathTracerResult result = render(scene, settings, 1);
    const gpu::GpuCamera camera = gi::makeGpuCamera(scene.camera, kSize, kSize);
    uint32_t misses = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec3 origin = gpu::cameraPosition(camera);
            const glm::vec3 d = gpu::cameraRayDirection(camera, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
            const float t = -origin.y / d.y;
            const glm::vec3 p = origin + t * d;
            if (t > 0.0f && std::abs(p.x) <= 1.01f && std::abs(p.z) <= 1.01f) {
                continue; // the floor (or too near its edge to call)
            }
            const glm::vec3 want = scene::skyRadiance(scene, d);
            const image::Rgb got = result.image.rgbAt(x, y);
            EXPECT_NEAR(got.r, want.r, 1e-3f + 1e-3f * want.r) << "pixel " << x << "," << y;
            EXPECT_NEAR(got.g, want.g, 1e-3f + 1e-3f * want.g) << "pixel " << x << "," << y;
            EXPECT_NEAR(got.b, want.b, 1e-3f + 1e-3f * want.b) << "pixel " << x << "," << y;
            ++misses;
        }
    }
    EXPECT_GT(misses, kSize * kSize / 2);
}

// Mean radiance over the pixels that see the floor well inside its edges.
glm::vec3 floorMean(const gi::PathTracerResult& result) {
    glm::dvec3 sum(0.0);
    uint32_t count = 0;
    for (uint32_t y = kSize / 4; y < 3 * kSize / 4; ++y) {
        for (uint32_t x = kSize / 4; x < 3 * kSize / 4; ++x) {
            const image::Rgb c = result.image.rgbAt(x, y);
            sum += glm::dvec3(c.r, c.g, c.b);
            ++count;
        }
    }
    return glm::vec3(sum / double(count));
}

TEST_P(EnvironmentSkyTest, FloorIsLitFromAboveOnly) {
    const glm::vec3 sky(0.3f, 0.6f, 1.2f);
    const float albedo = 0.8f;
    gi::PathTracerSettings settings;
    settings.jitter = false;
    scene::Scene above = makeFloorScene(kSize);
    above.skyEnvironment = twoHemisphereSky(sky, glm::vec3(0.0f));
    scene::Scene below = makeFloorScene(kSize);
    below.skyEnvironment = twoHemisphereSky(glm::vec3(0.0f), sky);
    // Cosine-weighted samples of a constant hemisphere each carry rho L exactly; only samples
    // within half a texel row of the horizon (0.8 degrees) blend in the other half.
    const glm::vec3 lit = floorMean(render(above, settings, 16));
    const glm::vec3 dark = floorMean(render(below, settings, 16));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(lit[c], albedo * sky[c], 0.002f * sky[c]) << "channel " << c;
        EXPECT_LT(dark[c], 0.002f * sky[c]) << "channel " << c;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(EnvironmentSkyTest);

} // namespace
} // namespace lumina::test
