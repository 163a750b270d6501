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
// reference). Measured: mean 2.7e-5, max 1.8e-4 (see docs/gi_tests.md).
constexpr double kMaxFrameToFrameRelMse = 1e-3;
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
// below this: about four times the wander between converged frames of the static camera above
// (relMSE up to 0.0022 against the last frame, from frame 200 on).
constexpr double kRecoveredRelMse = 0.01;
// Recovery is the first frame that starts a run of this many recovered frames. The view after
// the cut wanders more than the published one: once recovered, it left 0.01 again from about frame
// 150 to 250 after the cut (up to relMSE 0.012, commit c9fb1b5; frames 75 to 145 were within
// 1e-4, and no surface-cache pass ran after the cut), so "every later frame" measured that
// excursion rather than the recovery. The excursions are bounded apart (kMaxWanderRelMse).
constexpr uint32_t kRecoveredRun = 32;
// Frames after a cut from which every later frame is recovered. Measured with the near field
// (commit f2f610a): from frame 23 after setCamera alone (relMSE 0.052 in the first frame), from
// frame 56 after setCamera + cameraCut() (0.34 in the first frame); before the near field 4 and 83. Without
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

// The first frame (1-based) that starts kRecoveredRun frames of the curve within
// kRecoveredRelMse; past the curve's end when none does.
uint32_t recoveredAfter(const std::vector<double>& curve) {
    uint32_t run = 0;
    for (uint32_t i = 0; i < curve.size(); ++i) {
        run = curve[i] < kRecoveredRelMse ? run + 1 : 0;
        if (run == kRecoveredRun) {
            return i + 2 - kRecoveredRun;
        }
    }
    return uint32_t(curve.size()) + 1;
}

// The curve's largest value from `frame` (1-based) on.
double largestFrom(const std::vector<double>& curve, uint32_t frame) {
    double largest = 0.0;
    for (uint32_t i = frame - 1; i < curve.size(); ++i) {
        largest = std::max(largest, curve[i]);
    }
    return largest;
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
    const std::vector<double> reprojectedCurve = recoveryCurve(h, "cut, setCamera alone");
    const uint32_t reprojected = recoveredAfter(reprojectedCurve);

    // Back to the published camera until converged, then the same cut without history.
    h.renderer().setCamera(h.scene().camera);
    h.render(kConvergedFrames);
    h.renderer().setCamera(other);
    h.renderer().cameraCut();
    const std::vector<double> resetCurve = recoveryCurve(h, "cut, setCamera + cameraCut()");
    const uint32_t reset = recoveredAfter(resetCurve);

    std::printf("%s %ux%u: %u frames within relMSE %.3g of the converged view from frame %u after setCamera "
                "alone, from frame %u after setCamera + cameraCut()\n",
                kScene, kSize, kSize, kRecoveredRun, kRecoveredRelMse, reprojected, reset);
    ASSERT_LE(reprojected, kRecoveryFramesReprojected);
    ASSERT_LE(reset, kRecoveryFramesReset);
    // Once recovered, the view wanders no further from its converged image than the static camera
    // may from its last frame.
    const double wanderReprojected = largestFrom(reprojectedCurve, reprojected);
    const double wanderReset = largestFrom(resetCurve, reset);
    std::printf("largest relMSE after recovering: %.4f (setCamera alone), %.4f (with cameraCut())\n",
                wanderReprojected, wanderReset);
    EXPECT_LE(wanderReprojected, kMaxWanderRelMse);
    EXPECT_LE(wanderReset, kMaxWanderRelMse);
}

LUMINA_INSTANTIATE_GPU_TEST(FrameStabilityStress);

} // namespace
} // namespace lumina::test
