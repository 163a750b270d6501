// SurfaceCache::update (gi/surface_cache/surface_cache.h): which passes run and which are
// skipped, and why; convergence stops radiosity and leaves the atlas unchanged; a moved
// object or a changed light restarts it.
#include "gi/scene/scene_loader.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/surface_cache_harness.h"

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
    EXPECT_FLOAT_EQ(grid.minAndVoxelSize.w, 4.0f / 62.0f);
    EXPECT_EQ(grid.dims, glm::uvec4(64, 64, 64, 0));
    EXPECT_FLOAT_EQ(grid.minAndVoxelSize.x, -2.0f - 4.0f / 62.0f);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 64), std::invalid_argument);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 3), std::invalid_argument);
    EXPECT_THROW(voxelGridOver({0.0f, 0.0f, 0.0f}, {1.0f, NAN, 1.0f}, 64), std::invalid_argument);
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
