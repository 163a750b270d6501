// Screen probes under a sky (probe_ray_shading.hlsl reads common/sky_sampling.hlsli along each
// ray that misses): a floor open to the sky, no light. Its irradiance is pi x the upper
// hemisphere's radiance: the same under a constant environment as under the equivalent uniform
// sky, all of it under a sky bright above, none under a sky bright only below.
#include "gi/scene/scene.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/scene/sky_test_scenes.h"
#include "tests/screen_probes/screen_probe_harness.h"

#include <cmath>
#include <cstdio>

namespace lumina::test {
namespace {

class ProbeSkyGpuTest : public GpuTest {};

// Frames of accumulation: the probes' temporal filter keeps 0.85 of the history (low noise by
// 24 frames under a smooth sky).
constexpr int kFrames = 24;
const glm::vec3 kSky(0.3f, 0.5f, 0.9f);

// Mean irradiance over the floor's pixels (the GBuffer's surface pixels).
glm::vec3 floorIrradiance(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene) {
    ScreenProbeHarness harness(device, shaders, std::move(scene), kSize, kSize);
    for (int frame = 0; frame < kFrames; ++frame) {
        harness.render();
    }
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image result = harness.read(harness.probes().irradiance());
    glm::dvec3 sum(0.0);
    uint32_t count = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (normal.at("A", x, y) == 0.0f) {
                continue;
            }
            const image::Rgb e = result.rgbAt(x, y);
            sum += glm::dvec3(e.r, e.g, e.b);
            ++count;
        }
    }
    EXPECT_GT(count, kSize * kSize / 4) << "the floor fills much of the view";
    const glm::vec3 mean = glm::vec3(sum / double(std::max(count, 1u)));
    std::printf("floor irradiance over %u pixels: (%.5f, %.5f, %.5f)\n", count, mean.r, mean.g, mean.b);
    return mean;
}

TEST_P(ProbeSkyGpuTest, ConstantEnvironmentMatchesTheUniformSky) {
    LUMINA_REQUIRE_KERNELS();
    scene::Scene uniform = makeFloorScene(kSize);
    uniform.sky = kSky;
    scene::Scene environment = makeFloorScene(kSize);
    environment.skyEnvironment = twoHemisphereSky(kSky, kSky, 8, 4);
    const glm::vec3 a = floorIrradiance(device(), shaders(), uniform);
    const glm::vec3 b = floorIrradiance(device(), shaders(), environment);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a[c], kPi * kSky[c], 0.01f * kPi * kSky[c]) << "uniform, channel " << c;
        EXPECT_NEAR(b[c], a[c], 1e-4f * a[c]) << "environment, channel " << c;
    }
}

TEST_P(ProbeSkyGpuTest, EnvironmentIsReadAlongEachRay) {
    LUMINA_REQUIRE_KERNELS();
    scene::Scene above = makeFloorScene(kSize);
    above.skyEnvironment = twoHemisphereSky(kSky, glm::vec3(0.0f));
    scene::Scene below = makeFloorScene(kSize);
    below.skyEnvironment = twoHemisphereSky(glm::vec3(0.0f), kSky);
    const glm::vec3 lit = floorIrradiance(device(), shaders(), above);
    const glm::vec3 dark = floorIrradiance(device(), shaders(), below);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(lit[c], kPi * kSky[c], 0.01f * kPi * kSky[c]) << "bright above, channel " << c;
        EXPECT_LT(dark[c], 0.01f * kPi * kSky[c]) << "bright below, channel " << c;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(ProbeSkyGpuTest);

} // namespace
} // namespace lumina::test
