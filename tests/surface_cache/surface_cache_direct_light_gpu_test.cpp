// The surface cache's direct light (gi/surface_cache/surface_cache_direct_light_pass.h): a
// floor card under a point light against the analytic Lambert value, with the deferred
// renderer's lights and shadow maps; it runs only where lights or cards changed.
#include "gi/deferred/deferred_renderer.h"
#include "gi/scene/mesh_builder.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <cmath>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class SurfaceCacheDirectLightGpu : public GpuTest {};

constexpr float kAlbedo = 0.5f;
constexpr float kIntensity = 4.0f;
constexpr float kHeight = 1.0f;

// A 2 x 2 floor facing +y at y = 0 under a point light at height 1.
scene::Scene floorUnderALight() {
    scene::Scene s;
    s.name = "floor under a point light";
    s.materials.push_back({.name = "grey", .baseColor = glm::vec4(glm::vec3(kAlbedo), 1.0f)});
    scene::MeshBuilder b("floor");
    b.material(0);
    b.quad({-1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, -1.0f}, {-1.0f, 0.0f, -1.0f});
    s.meshes.push_back(b.finish());
    s.instances.push_back({.mesh = 0, .transform = glm::mat4(1.0f), .name = "floor"});
    s.lights.push_back({.type = scene::LightType::Point,
                        .name = "bulb",
                        .intensity = kIntensity,
                        .position = {0.0f, kHeight, 0.0f}});
    s.image = {64, 64};
    scene::finishCamera(s);
    return s;
}

SurfaceCacheSettings settings() {
    SurfaceCacheSettings s;
    s.atlasSize = 128;
    s.texelsPerUnit = 32.0f; // the floor takes one tile
    return s;
}

TEST_P(SurfaceCacheDirectLightGpu, AFloorUnderAPointLightGetsTheLambertIrradiance) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheHarness h(device(), shaders(), floorUnderALight(), settings());
    gi::DeferredRenderer renderer(
        device(), h.scene, h.gpuScene,
        {.sunShadowSize = 64, .pointShadowSize = 64, .log = [](std::string_view) {}});
    const auto lit = [&](gi::FrameContext& frame) -> std::optional<gi::ShadowedLights> {
        renderer.render(frame);
        return renderer.shadowedLights();
    };
    std::vector<gi::SkippedPass> skipped = h.update(lit);
    EXPECT_EQ(skipReason(skipped, SurfaceCacheDirectLightPass::kPassName), "");
    // One more update: combine reads this update's direct light, the next one the bounce.
    skipped = h.update(lit);
    EXPECT_EQ(skipReason(skipped, SurfaceCacheDirectLightPass::kPassName), "no light, shadow or card changed");

    const std::vector<glm::vec4> direct = h.cache.readLayer(AtlasLayer::DirectLight);
    const std::vector<glm::vec4> final = h.cache.readLayer(AtlasLayer::FinalLighting);
    const std::vector<glm::vec4> normal = h.cache.readLayer(AtlasLayer::Normal);
    const std::vector<glm::vec3> world = atlasWorldPositions(device(), h.cache);
    uint32_t checked = 0;
    float worst = 0.0f;
    for (size_t i = 0; i < direct.size(); ++i) {
        if (normal[i].a == 0.0f) {
            EXPECT_EQ(direct[i], glm::vec4(0.0f)) << "texel " << i << ": no surface, no light";
            continue;
        }
        // E = I cos(theta) / d^2 with cos(theta) = height / d.
        const glm::vec3 toLight = glm::vec3(0.0f, kHeight, 0.0f) - world[i];
        const float d = glm::length(toLight);
        const float expected = kIntensity * (kHeight / d) / (d * d);
        const float rel = std::abs(direct[i].r - expected) / expected;
        worst = std::max(worst, rel);
        ASSERT_LT(rel, 0.01f) << "texel " << i << " at (" << world[i].x << ", " << world[i].z
                              << "): " << direct[i].r << " for " << expected;
        // Nothing else in the scene: the final radiance is the Lambert reflection alone.
        ASSERT_NEAR(final[i].r, direct[i].r * kAlbedo / 3.14159265f, 2e-3f * final[i].r) << "texel " << i;
        ++checked;
    }
    EXPECT_GT(checked, 60u * 60u);
    std::printf("direct light: %u texels, worst relative error %.5f\n", checked, worst);
}

TEST_P(SurfaceCacheDirectLightGpu, AnOccluderCastsTheDeferredRenderersShadow) {
    LUMINA_REQUIRE_KERNELS();
    scene::Scene scene = floorUnderALight();
    // A 0.4 x 0.4 lid halfway up: its shadow on the floor is 0.8 x 0.8 around the centre.
    scene::MeshBuilder b("lid");
    b.material(0);
    b.quad({-0.2f, 0.5f, 0.2f}, {0.2f, 0.5f, 0.2f}, {0.2f, 0.5f, -0.2f}, {-0.2f, 0.5f, -0.2f});
    scene.meshes.push_back(b.finish());
    scene.instances.push_back({.mesh = 1, .transform = glm::mat4(1.0f), .name = "lid"});
    SurfaceCacheHarness h(device(), shaders(), std::move(scene), settings());
    gi::DeferredRenderer renderer(
        device(), h.scene, h.gpuScene,
        {.sunShadowSize = 64, .pointShadowSize = 128, .log = [](std::string_view) {}});
    h.update([&](gi::FrameContext& frame) -> std::optional<gi::ShadowedLights> {
        renderer.render(frame);
        return renderer.shadowedLights();
    });
    const std::vector<glm::vec4> direct = h.cache.readLayer(AtlasLayer::DirectLight);
    const std::vector<glm::vec4> normal = h.cache.readLayer(AtlasLayer::Normal);
    const std::vector<glm::vec3> world = atlasWorldPositions(device(), h.cache);
    const uint32_t floorCard = h.cache.cards().firstCard(0);
    const glm::uvec4 rect = h.cache.cards().cards()[floorCard].atlasRect;
    uint32_t shadowed = 0, lit = 0;
    for (uint32_t y = rect.y; y < rect.y + rect.w; ++y) {
        for (uint32_t x = rect.x; x < rect.x + rect.z; ++x) {
            const size_t i = size_t(y) * h.cache.atlas().size() + x;
            const glm::vec3 p = world[i];
            if (normal[i].a == 0.0f) {
                continue;
            }
            // Well inside the shadow (|x|, |z| < 0.3) and well outside it (> 0.5), clear of the
            // PCF penumbra.
            if (std::max(std::abs(p.x), std::abs(p.z)) < 0.3f) {
                EXPECT_EQ(direct[i].r, 0.0f)
                    << "(" << p.x << ", " << p.z << ") should be in the lid's shadow";
                ++shadowed;
            } else if (std::max(std::abs(p.x), std::abs(p.z)) > 0.5f) {
                const float d = glm::length(glm::vec3(0.0f, kHeight, 0.0f) - p);
                EXPECT_NEAR(direct[i].r, kIntensity * kHeight / (d * d * d), 0.01f * direct[i].r)
                    << "(" << p.x << ", " << p.z << ") should be lit";
                ++lit;
            }
            if (::testing::Test::HasFailure()) {
                return;
            }
        }
    }
    EXPECT_GT(shadowed, 300u);
    EXPECT_GT(lit, 1500u);
}

TEST_P(SurfaceCacheDirectLightGpu, RelightsOnlyWhenALightOrCardChanges) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheHarness h(device(), shaders(), floorUnderALight(), settings());
    gi::DeferredRenderer renderer(
        device(), h.scene, h.gpuScene,
        {.sunShadowSize = 64, .pointShadowSize = 64, .log = [](std::string_view) {}});
    const auto lit = [&](gi::FrameContext& frame) -> std::optional<gi::ShadowedLights> {
        renderer.render(frame);
        return renderer.shadowedLights();
    };
    EXPECT_EQ(skipReason(h.update(), SurfaceCacheDirectLightPass::kPassName), "no lights given");
    EXPECT_EQ(skipReason(h.update(lit), SurfaceCacheDirectLightPass::kPassName), "");
    EXPECT_EQ(skipReason(h.update(lit), SurfaceCacheDirectLightPass::kPassName), "no light, shadow or card changed");
    const float before = h.cache.readLayer(AtlasLayer::DirectLight)[64 * 128 / 2 + 32].r;

    // Twice the intensity: relit, twice the irradiance.
    std::vector<scene::Light> brighter = h.scene.lights;
    brighter[0].intensity *= 2.0f;
    renderer.setLights(brighter);
    EXPECT_EQ(skipReason(h.update(lit), SurfaceCacheDirectLightPass::kPassName), "");
    const float after = h.cache.readLayer(AtlasLayer::DirectLight)[64 * 128 / 2 + 32].r;
    EXPECT_NEAR(after, 2.0f * before, 2e-3f * after);
    EXPECT_EQ(skipReason(h.update(lit), SurfaceCacheDirectLightPass::kPassName), "no light, shadow or card changed");
}

LUMINA_INSTANTIATE_GPU_TEST(SurfaceCacheDirectLightGpu);

} // namespace
} // namespace lumina::test
