// Async compute (docs/performance.md, change 3): a frame split into raster, async compute and
// gather lists (FrameRenderer's SplitFrame) renders exactly what one list renders, for every
// technique that moves passes to the compute queue, and a frame that must capture or relight
// cards keeps them on the graphics queue.
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr uint32_t kFrames = 8;

// The largest difference of any channel of any pixel (NaN counts as infinitely different).
float maxDifference(const image::Image& a, const image::Image& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    float worst = 0.0f;
    for (const char* channel : {"R", "G", "B"}) {
        const auto x = a.channel(channel);
        const auto y = b.channel(channel);
        for (size_t i = 0; i < a.pixelCount(); ++i) {
            const float d = std::abs(x[i] - y[i]);
            worst = std::isnan(d) ? INFINITY : std::max(worst, d);
        }
    }
    return worst;
}

class AsyncComputeFrameGpu : public GpuTest {
protected:
    FrameHarness harness(const std::string& sceneName, gi::GiTechnique technique) {
        FrameHarnessSettings settings{.width = kSize, .height = kSize, .technique = technique};
        settings.adjustDdgi = [](gi::DdgiSettings& ddgi) { ddgi.raysPerProbe = 64; };
        return FrameHarness(device(), shaders(), scene::loadScene(sceneName), settings);
    }

    // kFrames on one list and split, the image compared; returns the split run's async frames.
    uint32_t compareOneListWithSplit(const std::string& sceneName, gi::GiTechnique technique) {
        FrameHarness oneList = harness(sceneName, technique);
        FrameHarness split = harness(sceneName, technique);
        oneList.render(kFrames);
        const uint32_t asyncFrames = split.renderWithAsyncCompute(kFrames);
        EXPECT_EQ(maxDifference(oneList.hdr(), split.hdr()), 0.0f)
            << sceneName << ": the split frame must render exactly what one list renders";
        return asyncFrames;
    }
};

TEST_P(AsyncComputeFrameGpu, LumenSplitRendersWhatOneListRenders) {
    const uint32_t asyncFrames = compareOneListWithSplit("cornell_box", gi::GiTechnique::Lumen);
    // The first frame captures every card (a raster pass): it stays on the graphics queue; the
    // cache's later updates (radiosity, voxel lighting) are compute only.
    EXPECT_EQ(asyncFrames, kFrames - 1);
}

TEST_P(AsyncComputeFrameGpu, DdgiSplitRendersWhatOneListRenders) {
    const uint32_t asyncFrames = compareOneListWithSplit("cornell_box", gi::GiTechnique::Ddgi);
    EXPECT_EQ(asyncFrames, kFrames - 1);
}

TEST_P(AsyncComputeFrameGpu, DirectAndShGridKeepEverythingOnTheGraphicsQueue) {
    EXPECT_EQ(compareOneListWithSplit("cornell_box", gi::GiTechnique::Direct), 0u);
    EXPECT_EQ(compareOneListWithSplit("cornell_box", gi::GiTechnique::ShGrid), 0u);
}

// A light that moves relights cards from a shadow map rendered in the same frame: that frame's
// cache update stays on the graphics queue, and the images still agree after it.
TEST_P(AsyncComputeFrameGpu, AFrameThatRelightsCardsStaysOnTheGraphicsQueue) {
    FrameHarness oneList = harness("cornell_box_point", gi::GiTechnique::Lumen);
    FrameHarness split = harness("cornell_box_point", gi::GiTechnique::Lumen);
    oneList.render(kFrames / 2);
    uint32_t asyncFrames = split.renderWithAsyncCompute(kFrames / 2);
    std::vector<scene::Light> lights = oneList.scene().lights;
    lights.at(0).position.x += 40.0f;
    oneList.renderer().setLights(lights);
    split.renderer().setLights(lights);
    oneList.render(1);
    EXPECT_EQ(split.renderWithAsyncCompute(1), 0u) << "the frame that relights cards";
    oneList.render(kFrames / 2);
    asyncFrames += split.renderWithAsyncCompute(kFrames / 2);
    EXPECT_EQ(asyncFrames, kFrames - 1) << "every frame but the first and the relit one";
    EXPECT_EQ(maxDifference(oneList.hdr(), split.hdr()), 0.0f);
}

LUMINA_INSTANTIATE_GPU_TEST(AsyncComputeFrameGpu);

} // namespace
} // namespace lumina::test
