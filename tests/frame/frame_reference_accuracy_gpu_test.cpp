// The screen-probe gather's accuracy goal (docs/gi_tests.md): after convergence, the final image
// with GI has at most a tenth of the relMSE that the direct-only image (what a user gets with no
// GI) has against the same path-traced reference. The references are stored
// (tests/frame/data/<scene>_128x128.exr): 65,536 samples per pixel at pixel centres, made on the
// lent GPU, where they take seconds (lavapipe would take hours); their own noise is below 3e-4
// relMSE. Medium preset, the one `lumina render` uses, at 128 x 128 (16 x 16 probes).
//
// Regenerate after a change to the scenes or the path tracer:
//   lumina reference SCENE --size 128x128 --spp 65536 --pixel-centres --out
//   tests/frame/data/SCENE_128x128.exr
#include "gi/image/exr.h"
#include "gi/measure/metrics.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 128;
constexpr uint32_t kSettleFrames = 48; // as `lumina render` without --frames
constexpr double kGoal = 0.1;          // lumen's relMSE / direct-only's, at most

std::filesystem::path referencePath(const std::string& scene) {
    return std::filesystem::path(LUMINA_FRAME_TEST_DATA_DIR) / (scene + "_128x128.exr");
}

// a - b, channel by channel (R, G, B).
image::Image difference(const image::Image& a, const image::Image& b) {
    image::Image out = image::Image::rgb(a.width(), a.height());
    for (const char* c : {"R", "G", "B"}) {
        const auto x = a.channel(c);
        const auto y = b.channel(c);
        auto o = out.channel(c);
        for (size_t i = 0; i < o.size(); ++i) {
            o[i] = x[i] - y[i];
        }
    }
    return out;
}

class FrameVsStoredReferenceGpu : public GpuTestFixture,
                                  public ::testing::WithParamInterface<std::tuple<rhi::Api, const char*>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

TEST_P(FrameVsStoredReferenceGpu, LumenHasATenthOfTheDirectOnlyError) {
    LUMINA_REQUIRE_KERNELS();
    const std::string scene = std::get<1>(GetParam());
    const image::Image reference = rgbOnly(image::readExr(referencePath(scene)));
    ASSERT_EQ(reference.width(), kSize);
    ASSERT_EQ(reference.height(), kSize);
    FrameHarness h(device(), shaders(), scene::loadScene(scene),
                   {.width = kSize, .height = kSize, .preset = "medium"});
    const uint32_t frames = h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << scene << ": surface cache not converged after " << frames << " frames";

    const image::Image lumen = h.hdr();
    const image::Image direct = h.direct();
    ASSERT_EQ(measure::countNonFinite(lumen).total(), 0u);
    const double lumenRelMse = measure::relMse(reference, lumen);
    const double directRelMse = measure::relMse(reference, direct);
    // The indirect term: what lumen adds to the direct light, against what the path tracer has
    // beyond the same direct light (in the emissive box the path tracer's own direct/indirect
    // split puts the light's first bounce on the other side).
    const double indirectRelMse = measure::relMse(difference(reference, direct), difference(lumen, direct));
    std::printf("%s %ux%u medium: %u frames; relMSE lumen %.5f, direct only %.5f (lumen / direct %.3f), "
                "indirect term %.5f\n",
                scene.c_str(), kSize, kSize, frames, lumenRelMse, directRelMse, lumenRelMse / directRelMse,
                indirectRelMse);
    EXPECT_LE(lumenRelMse, kGoal * directRelMse);
}

std::string caseName(const ::testing::TestParamInfo<std::tuple<rhi::Api, const char*>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FrameVsStoredReferenceGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::Values("cornell_box", "cornell_box_point",
                                                              "open_top_box")),
                         caseName);

} // namespace
} // namespace lumina::test
