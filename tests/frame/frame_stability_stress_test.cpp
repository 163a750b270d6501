// The lumen frame over time (docs/gi_tests.md), cornell_box at 48x48, low preset:
//   - a static camera for 1,000 frames: every valid probe's history and irradiance tile, the
//     screen irradiance and the final HDR stay finite (read back every 100 frames), the image
//     changes little from frame to frame once converged, and does not drift;
//   - camera cuts, by FrameRenderer::setCamera alone (histories reprojected) and with
//     cameraCut() (no history): within a stated number of frames each is close to a
//     long-converged render from the new camera.
// Bounds are the figures measured on lavapipe when this was written, with margin; the figures
// are in the comments and in docs/gi_tests.md.
#include "gi/measure/metrics.h"
#include "gi/scene/scene_loader.h"
#include "shaders/screen_probes/screen_probe_shared.h"
#include "tests/frame/frame_harness.h"
#include "tests/frame/probe_health.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

using FrameStabilityStress = GpuTest;

constexpr uint32_t kSize = 48;
constexpr const char* kScene = "cornell_box";
constexpr uint32_t kSettleFrames = 48; // as in frame_accuracy_gpu_test.cpp

// ---- static camera ----

constexpr uint32_t kLongRunFrames = 1000;
constexpr uint32_t kCheckEvery = 100;
// The largest relMSE between consecutive frames after settling (the previous frame as the
// reference). Measured at commit 812e787: mean 8.9e-5, max 4.5e-4 on Vulkan; on D3D12 (whose
// rounding sends the probes' importance sampling down another path) mean 9.0e-5 and one step of
// 1.15e-3 (frame 519), where the floor in the image's bottom-right corner brightened 13-22 % in one
// frame and settled back over the next few (docs/gi_tests.md). A clamp against
// the probe's brightest texel gave 4.1e-3, no temporal accumulation 0.074.
constexpr double kMaxFrameToFrameRelMse = 2e-3;
// relMSE of every 100th frame from frame 200 on against the last: the image wanders (the
// probes' temporal filters and lighting PDF feed on their own history) but does not drift.
// Measured: at most 0.0022 (see docs/gi_tests.md).
constexpr uint32_t kWanderFrom = 200;
constexpr double kMaxWanderRelMse = 0.02;

TEST_P(FrameStabilityStress, StaticCameraStaysFiniteAndSteadyFor1000Frames) {
    LUMINA_REQUIRE_KERNELS();
    FrameHarness h(device(), shaders(), scene::loadScene(kScene), {.width = kSize, .height = kSize});
    h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << "surface cache not converged after " << h.frames() << " frames";
    const uint32_t settledAt = h.frames();

    image::Image previous = h.hdr();
    double maxStep = 0.0, sumStep = 0.0;
    uint32_t steps = 0, maxStepFrame = 0;
    std::vector<std::pair<uint32_t, image::Image>> checkpoints;
    while (h.frames() < kLongRunFrames) {
        h.render();
        image::Image hdr = h.hdr();
        ASSERT_EQ(measure::countNonFinite(hdr).total(), 0u) << "frame " << h.frames();
        const double step = measure::relMse(previous, hdr);
        sumStep += step;
        ++steps;
        if (step > maxStep) {
            maxStep = step;
            maxStepFrame = h.frames();
        }
        if (h.frames() % kCheckEvery == 0) {
            const ProbeHealth health = probeHealth(device(), h);
            EXPECT_GT(health.validProbes, 0u);
            EXPECT_EQ(health.nonFiniteHistory, 0u) << "frame " << h.frames();
            EXPECT_EQ(health.nonFiniteIrradiance, 0u) << "frame " << h.frames();
            EXPECT_EQ(health.nonFiniteScreen, 0u) << "frame " << h.frames();
            if (h.frames() >= kWanderFrom) {
                checkpoints.emplace_back(h.frames(), hdr);
            }
        }
        previous = std::move(hdr);
    }
    double wander = 0.0;
    uint32_t wanderFrame = 0;
    for (const auto& [frame, image] : checkpoints) {
        const double error = measure::relMse(previous, image);
        if (error > wander) {
            wander = error;
            wanderFrame = frame;
        }
    }
    std::printf(
        "%s %ux%u: settled after %u frames; frame-to-frame relMSE over %u frames: mean %.3g, max %.3g "
        "(frame %u); every %uth frame from %u against frame %u: relMSE at most %.3g (frame %u)\n",
        kScene, kSize, kSize, settledAt, steps, sumStep / std::max(steps, 1u), maxStep, maxStepFrame,
        kCheckEvery, kWanderFrom, h.frames(), wander, wanderFrame);
    h.timings().print(std::cout);
    EXPECT_LT(maxStep, kMaxFrameToFrameRelMse) << "at frame " << maxStepFrame;
    EXPECT_LT(wander, kMaxWanderRelMse) << "at frame " << wanderFrame;
}

// ---- camera cut ----

// A frame is "recovered" when its relMSE against the converged image from the same camera is
// below this: the static camera's wander bound above. The view after the cut wanders more than
// the published one: with no surface-cache pass running after the cut, its frames moved up to
// 0.012 (commit c9fb1b5) and 0.0134 (commit 6b81850) from its converged image long after they had
// first come within 0.01 of it, so a bound of 0.01 (four times the published view's wander) measured
// where that wander happened to peak, not the recovery (frame 175, then 87, against 48).
constexpr double kRecoveredRelMse = kMaxWanderRelMse;
// Frames after a cut from which every later frame is recovered. Measured at commit 6b81850: from
// frame 10 after setCamera alone (relMSE 0.060 in the first frame), from frame 36 after
// setCamera + cameraCut() (0.48 in the first frame). With a bound of 0.01 and the near field
// (commit f2f610a): 23 and 56; before the near field 4 and 83. Without
// history the probes' outlier clamp holds new radiance to 2x the texel's (or the probe's mean) history, so a
// texel that sees the light ramps up by at most 1 + 0.15 x (2 - 1) = 1.15x per frame it is hit
// (docs/gi_tests.md).
constexpr uint32_t kRecoveryFramesReprojected = 48;
constexpr uint32_t kRecoveryFramesReset = 160;
// Frames after settling that make the converged image of a camera, and frames kept after a cut.
constexpr uint32_t kConvergedFrames = 300;
constexpr uint32_t kFramesKept = 256;

// A view from inside the box's upper left front, looking down at the right wall and the tall
// block: little of it was on screen from the published camera.
scene::Camera cutCamera(const scene::Camera& original) {
    scene::Camera camera = original;
    camera.position = {120.0f, 450.0f, 80.0f};
    camera.forward = glm::normalize(glm::vec3(430.0f, 100.0f, 420.0f) - camera.position);
    camera.up =
        glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), camera.forward));
    return camera;
}

// Renders kFramesKept frames after a cut, then kConvergedFrames more for the converged image;
// returns each kept frame's relMSE against it, and prints them.
std::vector<double> recoveryCurve(FrameHarness& h, const char* what) {
    std::vector<image::Image> kept;
    for (uint32_t i = 0; i < kFramesKept; ++i) {
        h.render();
        kept.push_back(h.hdr());
        EXPECT_EQ(measure::countNonFinite(kept.back()).total(), 0u) << what << ": frame " << i + 1;
    }
    h.render(kConvergedFrames);
    const image::Image converged = h.hdr();
    std::vector<double> curve;
    for (const image::Image& image : kept) {
        curve.push_back(measure::relMse(converged, image));
    }
    std::printf("%s: relMSE against the converged view after", what);
    for (uint32_t frame = 1; frame <= kFramesKept; frame *= 2) {
        std::printf(" %u: %.4f", frame, curve[frame - 1]);
    }
    std::printf("\n");
    return curve;
}

// The first frame (1-based) from which every frame of the curve is within kRecoveredRelMse.
uint32_t recoveredAfter(const std::vector<double>& curve) {
    uint32_t first = uint32_t(curve.size()) + 1;
    for (uint32_t i = uint32_t(curve.size()); i > 0 && curve[i - 1] < kRecoveredRelMse; --i) {
        first = i;
    }
    return first;
}

// Cut from the published camera to another view with setCamera alone (the probe and screen
// histories are reprojected in world space, and kept only where the surface is the same); later
// the same cut with setCamera + cameraCut() (no history at all).
TEST_P(FrameStabilityStress, CameraCutsRecoverWithinAStatedNumberOfFrames) {
    LUMINA_REQUIRE_KERNELS();
    FrameHarness h(device(), shaders(), scene::loadScene(kScene), {.width = kSize, .height = kSize});
    h.renderUntilConverged(kSettleFrames);
    ASSERT_TRUE(h.converged()) << "surface cache not converged after " << h.frames() << " frames";
    h.render(kConvergedFrames);

    const scene::Camera other = cutCamera(h.scene().camera);
    h.renderer().setCamera(other);
    const uint32_t reprojected = recoveredAfter(recoveryCurve(h, "cut, setCamera alone"));

    // Back to the published camera until converged, then the same cut without history.
    h.renderer().setCamera(h.scene().camera);
    h.render(kConvergedFrames);
    h.renderer().setCamera(other);
    h.renderer().cameraCut();
    const uint32_t reset = recoveredAfter(recoveryCurve(h, "cut, setCamera + cameraCut()"));

    std::printf("%s %ux%u: within relMSE %.3g of the converged view from frame %u after setCamera alone, "
                "from frame %u after setCamera + cameraCut()\n",
                kScene, kSize, kSize, kRecoveredRelMse, reprojected, reset);
    EXPECT_LE(reprojected, kRecoveryFramesReprojected);
    EXPECT_LE(reset, kRecoveryFramesReset);
}

LUMINA_INSTANTIATE_GPU_TEST(FrameStabilityStress);

} // namespace
} // namespace lumina::test
