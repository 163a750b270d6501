// Real scenes on lavapipe (issue: real scenes): atrium (210k triangles) and city (every building
// of the default 1024, 2.55 M triangles) render with lumen at every preset, at a small size and
// for a few frames: no exception (the surface cache degrades instead of overflowing), every pixel
// finite, the image lit, and on the city the card LOD at work (cards below full density).
#include "gi/measure/metrics.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <ostream>
#include <string>

namespace lumina::test {
namespace {

// Small: lavapipe rasterises the city's 2.55 M triangles for the GBuffer and every card capture.
constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 36;
constexpr uint32_t kFrames = 4;

struct RealSceneCase {
    const char* scene;
    const char* preset;
    bool overflows; // the cards do not fit the atlas at full density
};

void PrintTo(const RealSceneCase& c, std::ostream* out) {
    *out << c.scene << "_" << c.preset;
}

class RealScenesGpu : public GpuTestFixture,
                      public ::testing::WithParamInterface<std::tuple<rhi::Api, RealSceneCase>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

TEST_P(RealScenesGpu, LumenRendersFiniteAndLitAtEveryPreset) {
    LUMINA_REQUIRE_KERNELS();
    const RealSceneCase& c = std::get<1>(GetParam());
    FrameHarness h(device(), shaders(), scene::loadScene(c.scene),
                   {.width = kWidth, .height = kHeight, .preset = c.preset});
    h.render(kFrames);

    const image::Image hdr = h.hdr();
    const measure::NonFiniteCounts bad = measure::countNonFinite(hdr);
    EXPECT_EQ(bad.total(), 0u) << bad.nanPixels << " NaN, " << bad.infPixels << " Inf pixels";
    double sum = 0.0;
    for (uint32_t y = 0; y < hdr.height(); ++y) {
        for (uint32_t x = 0; x < hdr.width(); ++x) {
            sum += hdr.at("R", x, y) + hdr.at("G", x, y) + hdr.at("B", x, y);
        }
    }
    const double mean = sum / (3.0 * hdr.width() * hdr.height());
    EXPECT_GT(mean, 1e-3) << c.scene << " renders black";

    const surface_cache::AtlasOccupancy o = h.lumen().surfaceCache().cards().occupancy();
    SCOPED_TRACE(surface_cache::toString(o));
    EXPECT_LE(o.usedTiles, o.totalTiles);
    if (c.overflows) {
        EXPECT_LT(o.cardsAtLevel[0], o.cards) << "the LOD coarsened no card";
    } else {
        EXPECT_EQ(o.cardsAtLevel[0], o.cards);
    }
}

const RealSceneCase kCases[] = {
    {.scene = "atrium", .preset = "low", .overflows = false},
    {.scene = "atrium", .preset = "medium", .overflows = false},
    {.scene = "atrium", .preset = "high", .overflows = false},
    {.scene = "city", .preset = "low", .overflows = true},
    {.scene = "city", .preset = "medium", .overflows = true},
    {.scene = "city", .preset = "high", .overflows = true},
};

std::string caseName(const ::testing::TestParamInfo<std::tuple<rhi::Api, RealSceneCase>>& info) {
    const RealSceneCase& c = std::get<1>(info.param);
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + c.scene + "_" + c.preset;
}

INSTANTIATE_TEST_SUITE_P(Scenes, RealScenesGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::ValuesIn(kCases)),
                         caseName);

} // namespace
} // namespace lumina::test
