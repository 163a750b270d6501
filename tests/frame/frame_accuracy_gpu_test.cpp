// The lumen frame's accuracy (docs/gi_tests.md): FrameRenderer rendered until the surface
// cache has converged and the screen probes have settled, then
//   - white furnaces: every pixel's final radiance against the analytic Le / (1 - rho);
//   - Cornell boxes and the open-top box against the path tracer at the same pixel centres:
//     the final image's relMSE below the direct-only image's (what GI must at least buy), below
//     a regression bound around the figure measured when this was written, and the mean
//     radiance near the path tracer's.
// Bounds are regression bounds with margin (the near-field trace will move the figures a
// little); the measured figures are in the comments and in docs/gi_tests.md.
#include "gi/measure/metrics.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 64;
// Frames after the surface cache converged, as `lumina render` runs without --frames: the
// probes' temporal filter keeps 0.85 of the history a frame at the low preset (0.85^48 < 0.1%),
// the screen filter 0.7; the probes' outlier clamp makes them slower than that where a texel
// sees the light (docs/gi_tests.md, stability).
constexpr uint32_t kSettleFrames = 48;
constexpr uint32_t kReferenceSamples = 256;

// ---- furnaces ----

struct FurnaceCase {
    const char* scene;
    double albedo;
    double meanTolerance;  // |mean / exact - 1|
    double worstTolerance; // max over pixels and channels of |x / exact - 1|
};

// Readable parameters in gtest's and ctest's test lists.
void PrintTo(const FurnaceCase& c, std::ostream* out) {
    *out << c.scene;
}

class FrameFurnaceGpu : public GpuTestFixture,
                        public ::testing::WithParamInterface<std::tuple<rhi::Api, FurnaceCase>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

TEST_P(FrameFurnaceGpu, FinalRadianceIsLeOverOneMinusAlbedoEverywhere) {
    LUMINA_REQUIRE_KERNELS();
    const FurnaceCase& c = std::get<1>(GetParam());
    FrameHarness h(device(), shaders(), scene::loadScene(c.scene), {.width = kSize, .height = kSize});
    const uint32_t frames = h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << c.scene << ": surface cache not converged after " << frames << " frames";

    const double exact = 1.0 / (1.0 - c.albedo); // Le = 1 on every surface
    const image::Image hdr = h.hdr();
    EXPECT_EQ(measure::countNonFinite(hdr).total(), 0u);
    double sum = 0.0, worst = 0.0;
    uint32_t worstX = 0, worstY = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const image::Rgb v = hdr.rgbAt(x, y);
            for (const float value : {v.r, v.g, v.b}) {
                sum += value;
                const double error = std::abs(value / exact - 1.0);
                if (!(error <= worst)) { // NaN counts as the worst
                    worst = error;
                    worstX = x;
                    worstY = y;
                }
            }
        }
    }
    const double mean = sum / (3.0 * kSize * kSize);
    std::printf("%s: %u frames, mean %.5f (exact %.5f, %+.3f%%), worst pixel (%u, %u) %.3f%%\n", c.scene,
                frames, mean, exact, 100.0 * (mean / exact - 1.0), worstX, worstY, 100.0 * worst);
    h.timings().print(std::cout);
    EXPECT_NEAR(mean / exact, 1.0, c.meanTolerance);
    EXPECT_LE(worst, c.worstTolerance) << "at pixel (" << worstX << ", " << worstY << ")";
}

std::string furnaceName(const ::testing::TestParamInfo<std::tuple<rhi::Api, FurnaceCase>>& info) {
    std::string scene = std::get<1>(info.param).scene;
    std::replace(scene.begin(), scene.end(), '.', '_');
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + scene;
}

// Measured on lavapipe (64x64, low preset; docs/gi_tests.md): furnace_0.5 mean -0.017%, worst
// pixel 0.15%; furnace_0.8 mean -0.51%, worst pixel 1.09%. Since issue 26 (unbiased half
// rounding, dithered albedo, bounce cap 640): furnace_0.5 +0.098% / 0.098%, furnace_0.8 -0.156% /
// 0.156%; furnace_0.95 and furnace_0.99 (the goal: within 2 %) in docs/gi.md.
// The surface cache alone is within 0.31% at rho = 0.8 (docs/surface_cache.md); the screen
// probes' SH, their half-float atlas and the screen filter add the rest.
// After lumen began reading the side of a surface a ray sees (issue 26, sunlit_rooms),
// furnace_0.99 read -3.05% (worst pixel 3.06%): radiosity hits at the block's convex edges read
// zero (docs/gi.md, energy). Since the SDF gradient's side answers there: -0.597%, worst pixel
// 0.625% (683 frames, lavapipe); bounds 1% / 1% (were 3.5% / 3.5%; issue 26's goal 2%).
INSTANTIATE_TEST_SUITE_P(Scenes, FrameFurnaceGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::Values(FurnaceCase{"furnace_0.5", 0.5, 0.005, 0.01},
                                                              FurnaceCase{"furnace_0.8", 0.8, 0.015, 0.03},
                                                              FurnaceCase{"furnace_0.95", 0.95, 0.02, 0.03},
                                                              FurnaceCase{"furnace_0.99", 0.99, 0.01, 0.01})),
                         furnaceName);

// ---- against the path tracer ----

struct ReferenceCase {
    const char* scene;
    double relMseBound;   // regression bound on the final image's relMSE
    double meanTolerance; // |mean green / the path tracer's - 1|
};

void PrintTo(const ReferenceCase& c, std::ostream* out) {
    *out << c.scene;
}

class FrameVsPathTracerGpu : public GpuTestFixture,
                             public ::testing::WithParamInterface<std::tuple<rhi::Api, ReferenceCase>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

double meanGreen(const image::Image& image) {
    double sum = 0.0;
    for (const float g : image.channel("G")) {
        sum += g;
    }
    return sum / double(image.pixelCount());
}

TEST_P(FrameVsPathTracerGpu, LumenBeatsDirectOnly) {
    LUMINA_REQUIRE_KERNELS();
    const ReferenceCase& c = std::get<1>(GetParam());
    FrameHarness h(device(), shaders(), scene::loadScene(c.scene), {.width = kSize, .height = kSize});
    const gi::PathTracerResult traced =
        pathTracedReference(device(), h.pipelines(), h.scene(), kSize, kSize, kReferenceSamples);
    const image::Image reference = rgbOnly(traced.image);
    const uint32_t frames = h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << c.scene << ": surface cache not converged after " << frames << " frames";

    const image::Image lumen = h.hdr();
    const image::Image direct = h.direct(); // what the direct technique shows: no indirect term
    EXPECT_EQ(measure::countNonFinite(lumen).total(), 0u);
    const double lumenRelMse = measure::relMse(reference, lumen);
    const double directRelMse = measure::relMse(reference, direct);
    // The path tracer's indirect AOV is light after two or more bounces; lumen's GI term is the
    // final image less the deferred direct light (emission, lights). Sky light reflected once
    // is direct to the path tracer but GI to lumen (the probes gather the sky), so in the
    // open-top box the two terms differ by definition: printed, not bounded.
    const double indirectRelMse = measure::relMse(rgbOf(traced.image, "indirect"), h.indirect());
    const double meanRatio = meanGreen(lumen) / meanGreen(reference);
    std::printf("%s %ux%u: %u frames; relMSE lumen %.4f, direct only %.4f, indirect term %.4f; mean green "
                "lumen %.4f (%+.1f%%), direct %.4f, path tracer %.4f (%u spp, mean relative standard error "
                "%.4f)\n",
                c.scene, kSize, kSize, frames, lumenRelMse, directRelMse, indirectRelMse, meanGreen(lumen),
                100.0 * (meanRatio - 1.0), meanGreen(direct), meanGreen(reference), traced.samples,
                traced.meanRelativeStandardError);
    h.timings().print(std::cout);
    EXPECT_LT(lumenRelMse, directRelMse);
    EXPECT_LT(lumenRelMse, c.relMseBound);
    EXPECT_NEAR(meanRatio, 1.0, c.meanTolerance);
}

std::string referenceName(const ::testing::TestParamInfo<std::tuple<rhi::Api, ReferenceCase>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + std::get<1>(info.param).scene;
}

// Measured on lavapipe (64x64, low preset: 4 x 4 probes, 256 spp reference, whose own noise is a
// large part of these figures), commit 570d2b2: relMSE lumen / direct-only, mean green against the
// path tracer:
//   cornell_box_point  0.056 / 0.081, +4.3%
//   cornell_box        0.128 / 0.229, +19% (at 128x128, medium, the mean is within 2%)
//   open_top_box       0.135 / 0.403, +2.4%
// Since the one preset table (gi/frame/preset.h) the tests take the low preset's 1024^2 sun shadow
// map (it was 2048^2 here): open_top_box 0.155 / 0.425, +1.1% (the direct-only image moved with it).
// The goal, a tenth of direct-only's relMSE, is tested at 128x128 against 65,536-spp references
// (frame_reference_accuracy_gpu_test.cpp).
const ReferenceCase kReferenceCases[] = {
    {.scene = "cornell_box_point", .relMseBound = 0.075, .meanTolerance = 0.1},
    {.scene = "cornell_box", .relMseBound = 0.15, .meanTolerance = 0.3},
    {.scene = "open_top_box", .relMseBound = 0.17, .meanTolerance = 0.3},
};

INSTANTIATE_TEST_SUITE_P(Scenes, FrameVsPathTracerGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::ValuesIn(kReferenceCases)),
                         referenceName);

// ---- a thin occluder ----

class FrameClosedDoorGpu : public GpuTestFixture, public ::testing::WithParamInterface<rhi::Api> {
protected:
    void SetUp() override { openDevice(GetParam()); }
};

// The `door` scene as built (the door shut; the harness plays no animation): the camera's room
// gets only what passes the door's 1 cm gap. The radiosity filter once blended probes on the floor
// card across the 4 cm door, and at the low preset the dark room read 30 times the path tracer's
// mean (docs/gi.md, energy 12.). Lumen may miss the gap's light, as direct-only does, but may add
// none through the door.
TEST_P(FrameClosedDoorGpu, NoLightThroughTheDoor) {
    LUMINA_REQUIRE_KERNELS();
    FrameHarness h(device(), shaders(), scene::loadScene("door"), {.width = kSize, .height = kSize});
    const gi::PathTracerResult traced =
        pathTracedReference(device(), h.pipelines(), h.scene(), kSize, kSize, kReferenceSamples);
    const image::Image reference = rgbOnly(traced.image);
    const uint32_t frames = h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << "door: surface cache not converged after " << frames << " frames";

    const image::Image lumen = h.hdr();
    const double lumenRelMse = measure::relMse(reference, lumen);
    const double directRelMse = measure::relMse(reference, h.direct());
    std::printf("door %ux%u (closed), low: %u frames; relMSE lumen %.6f, direct only %.6f; mean green lumen "
                "%.6f, path tracer %.6f (%u spp)\n",
                kSize, kSize, frames, lumenRelMse, directRelMse, meanGreen(lumen), meanGreen(reference),
                traced.samples);
    // Measured on lavapipe: mean green lumen 2e-6 against the path tracer's 2.15e-4 (0.0072 before
    // the fix); relMSE 0.000498 against direct-only's 0.000499 (0.0073 before).
    EXPECT_LT(meanGreen(lumen), 3.0 * meanGreen(reference) + 1e-4);
    EXPECT_LT(lumenRelMse, 1.5 * directRelMse);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FrameClosedDoorGpu, ::testing::ValuesIn(app::compiledApis()),
                         [](const ::testing::TestParamInfo<rhi::Api>& info) {
                             return std::string(rhi::apiName(info.param));
                         });

} // namespace
} // namespace lumina::test
