// SurfaceCache::update (gi/surface_cache/surface_cache.h): which passes run and which are
// skipped, and why; convergence stops radiosity and leaves the atlas unchanged; a moved
// object or a changed light restarts it.
#include "gi/scene/scene_loader.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class SurfaceCacheUpdateGpu : public GpuTest {};

SurfaceCacheSettings smallAtlas() {
    SurfaceCacheSettings s;
    s.atlasSize = 256;
    s.texelsPerUnit = 16.0f;
    return s;
}

const char* const kLightingPasses[] = {
    SurfaceCacheCombinePass::kPassName,  VoxelLightingPass::kInjectPassName,
    VoxelLightingPass::kResolvePassName, RadiosityPass::kTracePassName,
    RadiosityPass::kFilterPassName,      RadiosityPass::kIntegratePassName};

constexpr const char* kConverged = "converged after 9 bounces and 16 refinement passes";

TEST_P(SurfaceCacheUpdateGpu, SkipsWhatDidNotChangeAndRestartsOnAMove) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheHarness h(device(), shaders(), scene::loadScene("furnace_0.5"), smallAtlas());

    // First update: everything runs.
    std::vector<gi::SkippedPass> skipped = h.update();
    EXPECT_EQ(skipReason(skipped, SurfaceCache::kCapturePassName), "");
    for (const char* pass : kLightingPasses) {
        EXPECT_EQ(skipReason(skipped, pass), "") << pass;
    }
    EXPECT_EQ(h.cache.cards().dirtyCards().size(), 0u) << "captured cards are no longer dirty";

    // Until converged: 9 bounces at rho = 0.5 (radiosity_schedule_test), then 16 refinement
    // passes; nothing to capture.
    ASSERT_EQ(h.cache.radiositySchedule().requiredBounces(), 9u);
    const uint32_t required = h.cache.radiositySchedule().requiredUpdates();
    ASSERT_EQ(required, 25u);
    for (uint32_t i = 1; i < required; ++i) {
        skipped = h.update();
        EXPECT_EQ(skipReason(skipped, SurfaceCache::kCapturePassName), "no dirty cards");
        EXPECT_EQ(skipReason(skipped, RadiosityPass::kTracePassName), "") << "update " << i;
    }
    // Converged: radiosity stops, combine still turns the last bounce into radiance...
    skipped = h.update();
    EXPECT_EQ(skipReason(skipped, RadiosityPass::kTracePassName), kConverged);
    EXPECT_EQ(skipReason(skipped, RadiosityPass::kIntegratePassName), kConverged);
    EXPECT_EQ(skipReason(skipped, SurfaceCacheCombinePass::kPassName), "");
    const std::vector<glm::vec4> converged = h.cache.readLayer(AtlasLayer::FinalLighting);
    // ...and then nothing runs at all, and nothing changes.
    for (int i = 0; i < 2; ++i) {
        skipped = h.update();
        EXPECT_EQ(skipReason(skipped, SurfaceCache::kCapturePassName), "no dirty cards");
        EXPECT_EQ(skipReason(skipped, SurfaceCacheCombinePass::kPassName), "nothing changed");
        EXPECT_EQ(skipReason(skipped, VoxelLightingPass::kInjectPassName), "nothing changed");
        EXPECT_EQ(skipReason(skipped, RadiosityPass::kTracePassName), kConverged);
    }
    EXPECT_EQ(h.cache.readLayer(AtlasLayer::FinalLighting), converged);

    // The block moves: its cards are captured again and radiosity restarts from zero bounces.
    const glm::mat4 moved = glm::translate(h.scene.instances[1].transform, {0.0f, 0.0f, -0.5f});
    h.scene.instances[1].transform = moved;
    h.sdf.setInstanceTransform(1, moved);
    h.cache.moveInstance(1, moved, h.scene.lights);
    skipped = h.update();
    EXPECT_EQ(skipReason(skipped, SurfaceCache::kCapturePassName), "");
    for (const char* pass : kLightingPasses) {
        EXPECT_EQ(skipReason(skipped, pass), "") << pass;
    }
    EXPECT_EQ(h.cache.radiositySchedule().completedBounces(), 1u);

    // A light change restarts radiosity alone.
    for (uint32_t i = 0; i < required + 1; ++i) {
        h.update();
    }
    EXPECT_EQ(skipReason(h.update(), RadiosityPass::kTracePassName), kConverged);
    h.cache.lightsChanged();
    skipped = h.update();
    EXPECT_EQ(skipReason(skipped, SurfaceCache::kCapturePassName), "no dirty cards");
    EXPECT_EQ(skipReason(skipped, RadiosityPass::kTracePassName), "");
}

TEST(SurfaceCacheVoxelGrid, CoversTheBoundsWithAVoxelOfMargin) {
    const gpu::VoxelGridInfo grid = voxelGridOver({-2.0f, -1.0f, 0.0f}, {2.0f, 1.0f, 0.5f}, 64);
    EXPECT_FLOAT_EQ(grid.voxelSize, 4.0f / 62.0f);
    EXPECT_EQ(grid.dims, glm::uvec3(64, 64, 64));
    EXPECT_FLOAT_EQ(grid.boxMin.x, -2.0f - 4.0f / 62.0f);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 64), std::invalid_argument);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 3), std::invalid_argument);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {1.0f, NAN, 1.0f}, 64), std::invalid_argument);
}

// A viewer walking across a city block whose cards do not fit the atlas at full density: the
// levels follow it on the GPU path (card buffer, tile-to-card lookup and tile lists re-uploaded,
// reallocated cards captured within the budget), every frame validation-clean, the atlas never
// over-full, the cards near the end of the walk finer than at its start, and once the captures
// catch up every lit texel finite.
TEST_P(SurfaceCacheUpdateGpu, AMovingViewerReallocatesCardsWithinTheBudgets) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheSettings settings;
    settings.atlasSize = 16 * kTileSize; // 256 tiles for ~350 cards of up to 8 x 8 tiles
    settings.texelsPerUnit = 4.0f;
    settings.lodChangesPerFrame = 16;
    settings.capturesPerFrame = 16;
    SurfaceCacheHarness h(device(), shaders(), scene::loadScene("city", {.instances = 16}), settings);
    const scene::Bounds bounds = h.scene.worldBounds();
    const glm::vec3 start(bounds.min.x, 2.0f, bounds.min.z);
    const glm::vec3 end(bounds.max.x, 2.0f, bounds.max.z);
    const SurfaceCards& cards = h.cache.cards();
    // The card nearest the end of the walk.
    uint32_t nearEnd = 0;
    for (uint32_t c = 1; c < cards.cards().size(); ++c) {
        if (cardPriority(cardBounds(cards.cards()[c]), end) >
            cardPriority(cardBounds(cards.cards()[nearEnd]), end)) {
            nearEnd = c;
        }
    }
    h.update({}, start);
    const uint8_t levelAtStart = cards.level(nearEnd);
    SCOPED_TRACE(toString(cards.occupancy()));
    ASSERT_LT(cards.occupancy().cardsAtLevel[0], cards.cards().size()) << "the atlas must overflow";

    uint32_t changed = 0;
    constexpr int kSteps = 12;
    for (int step = 1; step <= kSteps; ++step) {
        h.update({}, glm::mix(start, end, float(step) / kSteps));
        const CardLodUpdate& last = h.cache.lodHistory().last;
        EXPECT_LE(last.changed(), settings.lodChangesPerFrame) << "step " << step;
        changed += last.changed();
        const AtlasOccupancy o = cards.occupancy();
        ASSERT_LE(o.usedTiles, o.totalTiles);
    }
    EXPECT_GT(changed, 0u);
    for (int frame = 0;
         frame < 100 && (h.cache.lodHistory().pendingCaptures > 0 || h.cache.lodHistory().last.pending > 0);
         ++frame) {
        h.update({}, end);
    }
    EXPECT_EQ(h.cache.lodHistory().pendingCaptures, 0u);
    EXPECT_LT(cards.level(nearEnd), levelAtStart) << cards.describe(nearEnd);
    for (const glm::vec4& texel : h.cache.readLayer(AtlasLayer::FinalLighting)) {
        ASSERT_TRUE(std::isfinite(texel.r) && std::isfinite(texel.g) && std::isfinite(texel.b));
    }
}

TEST_P(SurfaceCacheUpdateGpu, ATileListRefusesTilesOutsideTheAtlas) {
    AtlasTileList list(device(), 4 * kTileSize, "test tiles");
    rhi::CommandListHandle commands = device().createCommandList();
    commands->begin();
    const std::vector<uint32_t> bad = {3, 16};
    try {
        list.recordUpload(*commands, bad);
        ADD_FAILURE() << "tile 16 of a 4x4-tile atlas was accepted";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("tile 16 of an atlas of 16 tiles"), std::string::npos)
            << e.what();
    }
    commands->end();
}

LUMINA_INSTANTIATE_GPU_TEST(SurfaceCacheUpdateGpu);

} // namespace
} // namespace lumina::test
