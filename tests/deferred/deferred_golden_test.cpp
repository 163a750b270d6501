// Goldens of the deferred renderer (docs/goldens.md): each GBuffer target and the final
// direct-only frame of cornell_box_point and open_top_box at 64x64, compared with
// tests/golden/data/ under the tolerances below. Regenerate with
//   LUMINA_UPDATE_GOLDENS=1 ctest -L golden      (Debian 12's lavapipe only)
#include "gi/scene/scene_loader.h"
#include "tests/deferred/deferred_harness.h"
#include "tests/golden/golden.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 64;

// Values in [0, 1] (albedo, display-encoded frame, normalised positions): a mean error under
// half an 8-bit step and 99% of pixels within a few steps; silhouette pixels that another
// rasteriser resolves differently fall in the last 1%.
constexpr GoldenTolerance kUnitRange{.meanAbsError = 0.002, .percentile = 0.99, .percentileError = 0.02};
// Unit normals span [-1, 1].
constexpr GoldenTolerance kNormals{.meanAbsError = 0.004, .percentile = 0.99, .percentileError = 0.04};
// Emission (radiance) and the material index: exact here, an index may differ at silhouettes.
constexpr GoldenTolerance kMaterial{.meanAbsError = 0.01, .percentile = 0.99, .percentileError = 0.05};
// Perspective depth crowds towards 1: much finer steps matter.
constexpr GoldenTolerance kDepth{.meanAbsError = 1e-4, .percentile = 0.99, .percentileError = 1e-3};

GoldenSpec spec(const std::string& scene, const char* target, GoldenTolerance tolerance,
                float previewMin = 0.0f, float previewMax = 1.0f) {
    GoldenSpec out;
    out.name = scene + "_" + target;
    out.tolerance = tolerance;
    out.previewMin = previewMin;
    out.previewMax = previewMax;
    return out;
}

// World positions mapped into the scene's bounds ([0, 1] along the longest side) and view
// depth by the same scale, so one tolerance fits every scene; background stays 0.
image::Image normalisedPositions(const image::Image& position, const image::Image& normal,
                                 const scene::Bounds& bounds) {
    const glm::vec3 size = bounds.size();
    const float scale = 1.0f / std::max({size.x, size.y, size.z});
    image::Image out = position;
    const char* channels[4] = {"R", "G", "B", "A"};
    const float offsets[4] = {bounds.min.x, bounds.min.y, bounds.min.z, 0.0f};
    const std::span<const float> covered = normal.channel("A");
    for (int c = 0; c < 4; ++c) {
        const std::span<float> values = out.channel(channels[c]);
        for (size_t i = 0; i < values.size(); ++i) {
            values[i] = covered[i] > 0.0f ? (values[i] - offsets[c]) * scale : 0.0f;
        }
    }
    return out;
}

class DeferredGoldenTest : public GpuTestFixture,
                           public ::testing::WithParamInterface<std::tuple<rhi::Api, std::string>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

TEST_P(DeferredGoldenTest, GBufferTargetsAndDirectFrameMatchTheirGoldens) {
    const std::string name = std::get<1>(GetParam());
    DeferredHarness harness(device(), shaders(), scene::loadScene(name), kSize, kSize);
    harness.render();
    const gi::GBuffer& gbuffer = harness.renderer().gbuffer();
    const image::Image normal = harness.read(gbuffer.normal);
    image::Image depth = harness.read(gbuffer.depth);
    // Depth lives in R; zeroed G and B keep the stored golden small.
    std::ranges::fill(depth.channel("G"), 0.0f);
    std::ranges::fill(depth.channel("B"), 0.0f);
    GoldenSpec depthSpec = spec(name, "depth", kDepth, 0.98f, 1.0f);
    depthSpec.pixelType = image::ExrPixelType::Float;

    const std::vector<std::pair<GoldenSpec, image::Image>> checks = {
        {spec(name, "albedo", kUnitRange), harness.read(gbuffer.albedo)},
        {spec(name, "normal", kNormals, -1.0f, 1.0f), normal},
        {spec(name, "material", kMaterial, 0.0f, 4.0f), harness.read(gbuffer.material)},
        {spec(name, "position", kUnitRange, 0.0f, 1.5f),
         normalisedPositions(harness.read(gbuffer.position), normal, harness.scene().worldBounds())},
        {depthSpec, depth},
        {spec(name, "frame", kUnitRange), harness.read(harness.renderer().ldr())},
    };
    for (const auto& [golden, image] : checks) {
        const GoldenResult result = checkGolden(golden, image, device().adapter());
        EXPECT_TRUE(result.passed) << result.message;
        std::cout << result.message << '\n';
    }
}

std::string goldenTestName(const ::testing::TestParamInfo<std::tuple<rhi::Api, std::string>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DeferredGoldenTest,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::Values(std::string("cornell_box_point"),
                                                              std::string("open_top_box"))),
                         goldenTestName);

} // namespace
} // namespace lumina::test
