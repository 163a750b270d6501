// Surface-cache radiosity under a sky (shaders/surface_cache/radiosity.hlsl): rays that leave the
// scene read the sky texture (common/sky_sampling.hlsli). A floor open to the sky, no light:
// its upward card's indirect irradiance is pi x the upper hemisphere's radiance, exactly (the
// stratified rays project a uniform hemisphere exactly, radiosity.hlsl), whether the sky is
// uniform or an environment; a floor under a sky that is bright only below it gets nothing.
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/scene/sky_test_scenes.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <cmath>
#include <cstdio>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class SkyRadiosityGpu : public GpuTest {};

constexpr float kPi = 3.14159265358979f;

SurfaceCacheSettings floorSettings() {
    SurfaceCacheSettings s;
    s.atlasSize = 256;
    s.texelsPerUnit = 16.0f; // the 2 m floor: 32 texels, one tile
    return s;
}

struct UpwardIrradiance {
    uint32_t texels = 0;
    glm::vec3 mean{0.0f};
    float maxDeviation = 0.0f; // largest |texel - mean| over channels
};

// The indirect layer over the captured texels facing up, once radiosity has converged.
UpwardIrradiance floorIrradiance(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene) {
    SurfaceCacheHarness h(device, shaders, std::move(scene), floorSettings());
    const uint32_t limit = h.cache.radiositySchedule().requiredUpdates() + 4;
    for (uint32_t update = 0; update < limit; ++update) {
        const auto skipped = h.update();
        if (!skipReason(skipped, RadiosityPass::kTracePassName).empty()) {
            break;
        }
    }
    const std::vector<glm::vec4> indirect = h.cache.readLayer(AtlasLayer::IndirectLight);
    const std::vector<glm::vec4> normal = h.cache.readLayer(AtlasLayer::Normal);
    UpwardIrradiance out;
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < indirect.size(); ++i) {
        if (normal[i].a != 0.0f && normal[i].y > 0.9f) {
            sum += glm::dvec3(indirect[i]);
            ++out.texels;
        }
    }
    out.mean = out.texels ? glm::vec3(sum / double(out.texels)) : glm::vec3(0.0f);
    for (size_t i = 0; i < indirect.size(); ++i) {
        if (normal[i].a != 0.0f && normal[i].y > 0.9f) {
            for (int c = 0; c < 3; ++c) {
                out.maxDeviation = std::max(out.maxDeviation, std::abs(indirect[i][c] - out.mean[c]));
            }
        }
    }
    std::printf("%u upward texels, mean indirect (%.5f, %.5f, %.5f), max deviation %.5f\n", out.texels,
                out.mean.r, out.mean.g, out.mean.b, out.maxDeviation);
    return out;
}

const glm::vec3 kSky(0.3f, 0.5f, 0.9f);

TEST_P(SkyRadiosityGpu, UniformSkyGivesPiTimesItsRadiance) {
    LUMINA_REQUIRE_KERNELS();
    scene::Scene scene = makeFloorScene(32);
    scene.sky = kSky;
    const UpwardIrradiance e = floorIrradiance(device(), shaders(), scene);
    ASSERT_GT(e.texels, 200u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(e.mean[c], kPi * kSky[c], 0.01f * kPi * kSky[c]) << "channel " << c;
    }
}

TEST_P(SkyRadiosityGpu, ConstantEnvironmentMatchesTheUniformSky) {
    LUMINA_REQUIRE_KERNELS();
    scene::Scene uniform = makeFloorScene(32);
    uniform.sky = kSky;
    scene::Scene environment = makeFloorScene(32);
    environment.skyEnvironment = twoHemisphereSky(kSky, kSky, 8, 4);
    const UpwardIrradiance a = floorIrradiance(device(), shaders(), uniform);
    const UpwardIrradiance b = floorIrradiance(device(), shaders(), environment);
    ASSERT_EQ(a.texels, b.texels);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a.mean[c], b.mean[c], 1e-5f * kPi * kSky[c]) << "channel " << c;
    }
}

TEST_P(SkyRadiosityGpu, EnvironmentIsReadAlongEachRay) {
    LUMINA_REQUIRE_KERNELS();
    // Bright above: the floor sees it all. Bright below: the floor sees none of it.
    scene::Scene above = makeFloorScene(32);
    above.skyEnvironment = twoHemisphereSky(kSky, glm::vec3(0.0f));
    scene::Scene below = makeFloorScene(32);
    below.skyEnvironment = twoHemisphereSky(glm::vec3(0.0f), kSky);
    const UpwardIrradiance up = floorIrradiance(device(), shaders(), above);
    const UpwardIrradiance down = floorIrradiance(device(), shaders(), below);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(up.mean[c], kPi * kSky[c], 0.01f * kPi * kSky[c]) << "channel " << c;
        EXPECT_LT(down.mean[c], 0.001f * kPi * kSky[c]) << "channel " << c;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(SkyRadiosityGpu);

} // namespace
} // namespace lumina::test
