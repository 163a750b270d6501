// Dynamic scenes through FrameRenderer's update API (docs/dynamic_scenes.md): what a change
// recomputes, checked against a fresh build of the changed scene, and the history it drops.
#include "gi/scene/scene_loader.h"
#include "gi/sdf/sdf_views.h"
#include "gi/surface_cache/surface_cache.h"
#include "rhi/transfer.h"
#include "shaders/screen_probes/screen_probe_shared.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 48;

uint32_t instanceNamed(const scene::Scene& scene, const std::string& name) {
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].name == name) {
            return i;
        }
    }
    throw std::runtime_error("no instance '" + name + "' in " + scene.name);
}

// The direct-light layer summed over an instance's cards (luminance-free: r + g + b).
double directOnCards(const gi::LumenGi& lumen, uint32_t instance) {
    const surface_cache::SurfaceCache& cache = lumen.surfaceCache();
    const std::vector<glm::vec4> texels = cache.readLayer(surface_cache::AtlasLayer::DirectLight);
    const uint32_t atlas = cache.atlas().size();
    double sum = 0.0;
    const surface_cache::SurfaceCards& cards = cache.cards();
    for (uint32_t card = cards.firstCard(instance);
         card < cards.firstCard(instance) + cards.cardCount(instance); ++card) {
        const glm::uvec4 rect = cards.cards()[card].atlasRect;
        for (uint32_t y = rect.y; y < rect.y + rect.w; ++y) {
            for (uint32_t x = rect.x; x < rect.x + rect.z; ++x) {
                const glm::vec4& t = texels[size_t(y) * atlas + x];
                sum += double(t.r) + t.g + t.b;
            }
        }
    }
    return sum;
}

class DynamicSceneGpu : public GpuTest {
protected:
    FrameHarness harness(scene::Scene scene, uint32_t probeSpacing = 0) {
        return FrameHarness(device(), shaders(), std::move(scene),
                            {.width = kSize, .height = kSize, .probeSpacing = probeSpacing});
    }
};

// The bug the light masks had: computed once at placement, a ranged light moved next to a card
// it could not reach before never lit it.
TEST_P(DynamicSceneGpu, ARangedLightMovedNextToACardLightsIt) {
    scene::Scene scene = scene::loadScene("cornell_box_point");
    scene.lights.at(0).range = 150.0f;
    scene.lights.at(0).position = {160.0f, 300.0f, 140.0f}; // above the short block
    const uint32_t tall = instanceNamed(scene, "tall block");
    FrameHarness h = harness(scene);
    h.render(2);
    EXPECT_EQ(directOnCards(h.lumen(), tall), 0.0) << "the light is out of the tall block's reach";
    const uint32_t cardsOfTall = h.lumen().surfaceCache().cards().firstCard(tall);
    EXPECT_EQ(h.lumen().surfaceCache().cards().cards()[cardsOfTall].lightMask, glm::uvec4(0u));

    std::vector<scene::Light> lights = scene.lights;
    lights[0].position = {350.0f, 380.0f, 380.0f}; // over the tall block
    h.renderer().setLights(lights);
    h.render();
    EXPECT_EQ(h.renderer().lastChanges().changedLights, 1u);
    EXPECT_NE(h.lumen().surfaceCache().cards().cards()[cardsOfTall].lightMask, glm::uvec4(0u));
    EXPECT_GT(directOnCards(h.lumen(), tall), 0.0) << "the moved light must light the cards it reaches now";
}

// A moved block: its cards are placed as a fresh build of the moved scene places them, and the
// global SDF recomposed around it equals the fresh one, though only the bricks the move touched
// were composed again.
TEST_P(DynamicSceneGpu, AMovedBlockMatchesAFreshBuildOfTheMovedScene) {
    const scene::Scene scene = scene::loadScene("cornell_box");
    const uint32_t block = instanceNamed(scene, "short block");
    const glm::mat4 moved =
        glm::translate(glm::mat4(1.0f), {150.0f, 0.0f, 120.0f}) * scene.instances[block].transform;
    scene::Scene movedScene = scene;
    movedScene.instances[block].transform = moved;

    FrameHarness h = harness(scene);
    h.render(2);
    h.renderer().moveInstance(block, moved);
    h.render();
    EXPECT_EQ(h.renderer().lastChanges().movedInstances, 1u);
    const sdf::GlobalComposeStats& compose = h.lumen().sdf().lastCompose();
    EXPECT_FALSE(compose.full);
    EXPECT_EQ(compose.changedInstances, 1u);
    h.render(); // the captures the budget left, if any

    FrameHarness fresh = harness(movedScene);
    fresh.render(2);
    const surface_cache::SurfaceCards& a = h.lumen().surfaceCache().cards();
    const surface_cache::SurfaceCards& b = fresh.lumen().surfaceCache().cards();
    ASSERT_EQ(a.cards().size(), b.cards().size());
    for (uint32_t card = a.firstCard(block); card < a.firstCard(block) + a.cardCount(block); ++card) {
        const scene::Bounds boundsA = surface_cache::cardBounds(a.cards()[card]);
        const scene::Bounds boundsB = surface_cache::cardBounds(b.cards()[card]);
        EXPECT_LT(glm::length(boundsA.min - boundsB.min) + glm::length(boundsA.max - boundsB.max), 1e-2f)
            << a.describe(card);
        EXPECT_EQ(a.cards()[card].lightMask, b.cards()[card].lightMask) << a.describe(card);
    }
    const sdf::GlobalSdf sdfA = sdf::readGlobalSdf(device(), h.lumen().sdf());
    const sdf::GlobalSdf sdfB = sdf::readGlobalSdf(device(), fresh.lumen().sdf());
    ASSERT_EQ(sdfA.distances.size(), sdfB.distances.size());
    float worst = 0.0f;
    for (size_t i = 0; i < sdfA.distances.size(); ++i) {
        worst = std::max(worst, std::abs(sdfA.distances[i] - sdfB.distances[i]));
    }
    EXPECT_LT(worst, 1e-3f * sdfA.voxelSize) << "the recomposed global SDF differs from a fresh one";
}

// Near a moved object the floor did not move, so reprojection alone would keep its history and the
// block's old shadow and bounce would trail; the change region drops it there, and only there.
TEST_P(DynamicSceneGpu, HistoryIsDroppedAroundAMovedObjectOnly) {
    const scene::Scene scene = scene::loadScene("cornell_box");
    const uint32_t block = instanceNamed(scene, "short block");
    FrameHarness h = harness(scene, 4); // enough floor probes around the block
    h.render(8);
    const glm::mat4 moved =
        glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, 60.0f}) * scene.instances[block].transform;
    h.renderer().moveInstance(block, moved);
    h.render();

    const gi::ScreenProbeGather& probes = h.lumen().screenProbes();
    const gi::ScreenProbeResources& r = probes.resources();
    const auto probeData = rhi::readBufferAs<gpu::ScreenProbe>(device(), *r.probes[probes.current()]);
    const auto history = rhi::readBufferAs<gpu::float4>(device(), *r.history[probes.current()]);
    const auto frameRadiance = rhi::readBufferAs<gpu::float4>(device(), *r.frameRadiance);
    const scene::Bounds local = scene.meshes[scene.instances[block].mesh].bounds;
    scene::Bounds near = scene::transformBounds(local, scene.instances[block].transform);
    near.extend(scene::transformBounds(local, moved));
    // Floor probes only (the floor is y = 0), well inside or well outside the dropped region.
    double insideRatio = 0.0, outsideRatio = 0.0;
    uint32_t inside = 0, outside = 0;
    for (uint32_t p = 0; p < probeData.size(); ++p) {
        const gpu::ScreenProbe& probe = probeData[p];
        if (probe.info.x == 0 || std::abs(probe.positionAndDepth.y) > 1.0f) {
            continue;
        }
        double weight = 0.0, fresh = 0.0;
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            weight += history[p * LUMINA_SP_PROBE_TEXELS + t].w;
            fresh += frameRadiance[p * LUMINA_SP_PROBE_TEXELS + t].w;
        }
        if (fresh <= 0.0) {
            continue;
        }
        const glm::vec3 at(probe.positionAndDepth.x, probe.positionAndDepth.y, probe.positionAndDepth.z);
        const float dx = std::max({near.min.x - at.x, 0.0f, at.x - near.max.x});
        const float dz = std::max({near.min.z - at.z, 0.0f, at.z - near.max.z});
        if (dx == 0.0f && dz == 0.0f) {
            continue; // under the block: it moved there or away, reprojection decides alone
        }
        if (std::max(dx, dz) < 40.0f) {
            insideRatio += weight / fresh;
            ++inside;
        } else if (std::max(dx, dz) > 180.0f) { // beyond the region's margin (half the box's diagonal)
            outsideRatio += weight / fresh;
            ++outside;
        }
    }
    ASSERT_GT(inside, 0u);
    ASSERT_GT(outside, 0u);
    insideRatio /= inside;
    outsideRatio /= outside;
    // A dropped history leaves this frame's weight alone (the blend's new share, 0.1 or so); a
    // kept one has nine frames of it.
    EXPECT_LT(insideRatio, 0.5 * outsideRatio) << "inside " << insideRatio << ", outside " << outsideRatio;
}

TEST_P(DynamicSceneGpu, BadEditsAreRefusedWithTheirReason) {
    FrameHarness h = harness(scene::loadScene("cornell_box"));
    EXPECT_THROW(h.renderer().moveInstance(99, glm::mat4(1.0f)), std::out_of_range);
    EXPECT_THROW(h.renderer().moveInstance(0, glm::mat4(0.0f)), std::invalid_argument);
    EXPECT_THROW(h.renderer().moveInstance(0, glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f})),
                 std::invalid_argument);
    scene::Light nan;
    nan.intensity = std::nanf("");
    EXPECT_THROW(h.renderer().setLights({nan}), std::invalid_argument);
    EXPECT_THROW(h.renderer().setEmission(0, glm::vec3(-1.0f)), std::invalid_argument);
    EXPECT_THROW(h.renderer().setEmission(1000, glm::vec3(1.0f)), std::out_of_range);
    h.render(); // nothing of the refused edits is applied
    EXPECT_FALSE(h.renderer().lastChanges().any());
}

LUMINA_INSTANTIATE_GPU_TEST(DynamicSceneGpu);

} // namespace
} // namespace lumina::test
