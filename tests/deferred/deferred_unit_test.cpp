// CPU halves of the deferred renderer: light setup and shadow slots, the sun's fitted
// projection, the cube-face convention shared with the kernels, point shadow ranges, and the
// grouping of draws by cull mode.
#include "gi/deferred/draw_lists.h"
#include "gi/deferred/light_setup.h"
#include "shaders/deferred/deferred_shared.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace lumina::gi {
namespace {

scene::Light light(scene::LightType type, glm::vec3 position = glm::vec3(0.0f)) {
    scene::Light out;
    out.type = type;
    out.position = position;
    out.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    return out;
}

TEST(DeferredLights, FirstSunAndFirstFourPointOrSpotLightsCastShadows) {
    using T = scene::LightType;
    const std::vector<scene::Light> lights = {light(T::Point),       light(T::Directional), light(T::Spot),
                                              light(T::Directional), light(T::Point),       light(T::Point),
                                              light(T::Point),       light(T::Spot)};
    const LightSetup setup = setupLights(lights);
    ASSERT_EQ(setup.lights.size(), lights.size());
    ASSERT_TRUE(setup.sun.has_value());
    EXPECT_EQ(*setup.sun, 1u);
    EXPECT_EQ(setup.cubeLights, (std::vector<uint32_t>{0, 2, 4, 5}));
    const uint32_t none = LUMINA_SHADOW_SLOT_NONE;
    const std::vector<uint32_t> slots = {0, 0, 1, none, 2, 3, none, none};
    for (size_t i = 0; i < lights.size(); ++i) {
        EXPECT_EQ(setup.lights[i].shadowSlot, slots[i]) << "light " << i;
        EXPECT_EQ(gpu::lightType(setup.lights[i].light), lights[i].type == T::Directional
                                                             ? LUMINA_LIGHT_DIRECTIONAL
                                                         : lights[i].type == T::Point ? LUMINA_LIGHT_POINT
                                                                                      : LUMINA_LIGHT_SPOT);
    }
    // The second sun and the point/spot lights beyond four are named in the log.
    ASSERT_EQ(setup.unshadowed.size(), 3u);
    EXPECT_NE(setup.unshadowed[0].find("directional light 3"), std::string::npos) << setup.unshadowed[0];
    EXPECT_NE(setup.unshadowed[1].find("point light 6"), std::string::npos) << setup.unshadowed[1];
    EXPECT_NE(setup.unshadowed[2].find("spot light 7"), std::string::npos) << setup.unshadowed[2];
}

glm::vec3 clipOf(const SunShadowFit& fit, const glm::vec3& p) {
    const glm::vec4 w(p, 1.0f);
    return {glm::dot(fit.viewProjRows[0], w), glm::dot(fit.viewProjRows[1], w),
            glm::dot(fit.viewProjRows[2], w)};
}

TEST(DeferredSunShadow, FitHoldsEveryCornerWithAMarginAndDepthGrowsAlongTheSun) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    constexpr uint32_t kSize = 2048;
    for (int trial = 0; trial < 200; ++trial) {
        scene::Bounds bounds;
        const glm::vec3 a(unit(random) * 50, unit(random) * 50, unit(random) * 50);
        bounds.extend(a);
        bounds.extend(a + glm::vec3(1 + 20 * (unit(random) + 1), 0.1f + (unit(random) + 1),
                                    1 + 5 * (unit(random) + 1)));
        glm::vec3 direction(unit(random), unit(random), unit(random));
        if (glm::length(direction) < 0.1f) {
            continue;
        }
        if (trial == 0) {
            direction = glm::vec3(0.0f, -1.0f, 0.0f); // straight down: the degenerate "up" case
        }
        const SunShadowFit fit = fitSunShadow(bounds, direction, kSize);
        const float margin = 2.0f * 2.0f / float(kSize); // two texels in clip units
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                              (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
            const glm::vec3 clip = clipOf(fit, p);
            EXPECT_LE(std::abs(clip.x), 1.0f - margin + 1e-4f) << "trial " << trial;
            EXPECT_LE(std::abs(clip.y), 1.0f - margin + 1e-4f) << "trial " << trial;
            EXPECT_GT(clip.z, 0.0f) << "trial " << trial;
            EXPECT_LT(clip.z, 1.0f) << "trial " << trial;
        }
        const glm::vec3 centre = bounds.centre();
        const glm::vec3 step = glm::normalize(direction) * 0.01f * fit.depthRange;
        EXPECT_NEAR(clipOf(fit, centre + step).z - clipOf(fit, centre).z, 0.01f, 1e-4f);
        EXPECT_NEAR(fit.texelWorld * kSize * 0.5f * glm::length(glm::vec3(fit.viewProjRows[0])), 1.0f, 1e-4f);
    }
}

TEST(DeferredCubeFaces, KnownDirectionsLandOnTheApiFaces) {
    // Vulkan spec, "Cube Map Face Selection": +X uses sc = -z, tc = -y.
    const gpu::float3 d(1.0f, 0.2f, -0.3f);
    ASSERT_EQ(gpu::cubeFaceOf(d), 0u);
    const gpu::float2 uv = gpu::cubeFaceUv(d, 0);
    EXPECT_NEAR(uv.x, 0.65f, 1e-6f);
    EXPECT_NEAR(uv.y, 0.4f, 1e-6f);
    EXPECT_EQ(gpu::cubeFaceOf(gpu::float3(0.1f, -2.0f, 0.5f)), 3u);
    EXPECT_EQ(gpu::cubeFaceOf(gpu::float3(0.1f, 0.2f, -0.5f)), 5u);
    // -Y: sc = x, tc = -z.
    const gpu::float2 down = gpu::cubeFaceUv(gpu::float3(0.5f, -1.0f, 0.25f), 3);
    EXPECT_NEAR(down.x, 0.75f, 1e-6f);
    EXPECT_NEAR(down.y, 0.375f, 1e-6f);
}

TEST(DeferredCubeFaces, RasterClipAndLookupAgree) {
    // What the point-shadow pass rasterises at a pixel is what the direct-light pass looks up
    // there: clip-space x = 2u - 1 and y = 1 - 2v (row 0 at the top), depth 0..1 near to far.
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float nearPlane = 0.01f, farPlane = 100.0f;
    for (int i = 0; i < 1000; ++i) {
        const gpu::float3 d(unit(random), unit(random), unit(random));
        if (glm::length(d) < 1e-3f) {
            continue;
        }
        const uint32_t face = gpu::cubeFaceOf(d);
        const gpu::float2 uv = gpu::cubeFaceUv(d, face);
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_GE(uv.y, 0.0f);
        ASSERT_LE(uv.y, 1.0f);
        const float distance = 0.1f + 50.0f * (unit(random) + 1.0f);
        const gpu::float4 clip =
            gpu::cubeFaceClip(d * (distance / glm::length(d)), face, nearPlane, farPlane);
        ASSERT_GT(clip.w, 0.0f);
        EXPECT_NEAR(clip.x / clip.w, 2.0f * uv.x - 1.0f, 1e-4f);
        EXPECT_NEAR(clip.y / clip.w, 1.0f - 2.0f * uv.y, 1e-4f);
        EXPECT_GE(clip.z / clip.w, 0.0f);
        EXPECT_LE(clip.z / clip.w, 1.0f);
    }
    // Depth is 0 at the near plane and 1 at the far plane along the major axis.
    EXPECT_NEAR(gpu::cubeFaceClip(gpu::float3(0, 0, nearPlane), 4, nearPlane, farPlane).z, 0.0f, 1e-6f);
    const gpu::float4 far = gpu::cubeFaceClip(gpu::float3(0, 0, -farPlane), 5, nearPlane, farPlane);
    EXPECT_NEAR(far.z / far.w, 1.0f, 1e-6f);
}

TEST(DeferredPointShadow, RangeCoversTheSceneOrStopsAtTheLightsRange) {
    scene::Bounds bounds;
    bounds.extend(glm::vec3(0.0f));
    bounds.extend(glm::vec3(10.0f, 4.0f, 10.0f));
    scene::Light point = light(scene::LightType::Point, glm::vec3(1.0f, 1.0f, 1.0f));
    const float farthest = glm::length(glm::vec3(9.0f, 3.0f, 9.0f));
    EXPECT_NEAR(pointShadowRange(point, bounds), farthest * 1.01f, 1e-4f);
    point.range = 5.0f;
    EXPECT_EQ(pointShadowRange(point, bounds), 5.0f);
    point.range = 1000.0f;
    EXPECT_NEAR(pointShadowRange(point, bounds), farthest * 1.01f, 1e-4f);
}

TEST(DeferredDrawLists, CullModeFollowsDoubleSidedAndMirroring) {
    scene::Scene scene;
    scene.materials = {{.name = "single"}, {.name = "double", .doubleSided = true}};
    scene.meshes.resize(1);
    scene.instances = {
        {.mesh = 0, .transform = glm::mat4(1.0f), .name = "plain"},
        {.mesh = 0, .transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1)), .name = "mirrored"},
        {.mesh = 0, .transform = glm::mat4(1.0f), .name = "plain again"}};
    std::vector<SceneDraw> draws;
    auto add = [&](uint32_t instance, uint32_t material, uint32_t first, uint32_t count) {
        SceneDraw draw{};
        draw.args.firstVertexOrIndex = first;
        draw.args.vertexOrIndexCount = count;
        draw.constants = {instance, material, 0, 0};
        draws.push_back(draw);
    };
    add(0, 0, 0, 6);  // single-sided: cull back
    add(0, 1, 6, 6);  // double-sided: no culling (same instance, contiguous)
    add(1, 0, 0, 6);  // mirrored single-sided: cull front
    add(1, 1, 6, 6);  // mirrored double-sided: no culling
    add(2, 0, 12, 3); // not contiguous with instance 1's range
    const GBufferDraws gbuffer = gbufferDraws(scene, draws);
    const auto& groups = gbuffer.groups;
    ASSERT_EQ(groups.size(), 3u);
    EXPECT_EQ(groups[0].cull, rhi::CullMode::Back);
    EXPECT_EQ(groups[0].draws.size(), 2u);
    EXPECT_EQ(groups[1].cull, rhi::CullMode::Front);
    EXPECT_EQ(groups[1].draws.size(), 1u);
    EXPECT_EQ(groups[2].cull, rhi::CullMode::None);
    EXPECT_EQ(groups[2].draws.size(), 2u);
    gpu::GBufferVisibilityDrawConstants pushed{};
    std::memcpy(&pushed, groups[1].draws[0].constants.data(), sizeof(pushed));
    EXPECT_EQ(pushed.instance, 1u);
    // Ids in drawing order from 1: back (2 + 1 triangles), then front (2), then none (2 + 2).
    EXPECT_EQ(pushed.firstId, 4u);
    EXPECT_EQ(gbuffer.triangleCount, 9u);
    ASSERT_EQ(gbuffer.resolveTable.size(), 5u);
    for (size_t i = 1; i < gbuffer.resolveTable.size(); ++i) {
        EXPECT_LT(gbuffer.resolveTable[i - 1].firstId, gbuffer.resolveTable[i].firstId);
    }
    EXPECT_EQ(gbuffer.resolveTable[2].instance, 1u);
    EXPECT_EQ(gbuffer.resolveTable[2].firstIndex, 0u);

    // Shadows: one range per instance where its submeshes are contiguous.
    const auto shadows = shadowDraws(draws);
    ASSERT_EQ(shadows.size(), 3u);
    EXPECT_EQ(shadows[0].instance, 0u);
    EXPECT_EQ(shadows[0].args.vertexOrIndexCount, 12u);
    EXPECT_EQ(shadows[1].instance, 1u);
    EXPECT_EQ(shadows[1].args.vertexOrIndexCount, 12u);
    EXPECT_EQ(shadows[2].instance, 2u);
    const auto faceDraws = shadowRasterDraws(shadows, 13);
    gpu::ShadowDrawConstants shadowPush{};
    std::memcpy(&shadowPush, faceDraws[2].constants.data(), sizeof(shadowPush));
    EXPECT_EQ(shadowPush.instance, 2u);
    EXPECT_EQ(shadowPush.layer, 13u);
}

} // namespace
} // namespace lumina::gi
