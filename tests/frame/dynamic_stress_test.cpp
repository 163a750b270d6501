// A dynamic scene over a long run (docs/gi_tests.md, docs/dynamic_scenes.md). Label `long`: on
// lavapipe a frame of it costs about 1.7 s (every frame re-renders the sun's shadow map, re-lights
// every card and restarts radiosity), so CI leaves it out (`ctest -LE long`) and
// scripts/gpu/dynamic_scenes.sh runs it on the lent GPU, where the figures in docs/gi_tests.md
// come from.
#include "gi/measure/metrics.h"
#include "gi/scene/scene_animation.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/frame/probe_health.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <cstdio>

namespace lumina::test {
namespace {

using DynamicStress = GpuTest;

constexpr uint32_t kCheckEvery = 100;

// atrium_day's sun sweeps from morning towards evening: 1,000 frames (of its 1,200-frame loop, so
// no jump back to morning) at 32 x 32, low preset, the sun's direction, colour and illuminance
// changing every frame. Each frame re-renders the sun's shadow map, re-lights every card,
// restarts radiosity and shortens history (docs/dynamic_scenes.md); nothing may turn non-finite
// and no frame may jump. Frame-to-frame relMSE measured on lavapipe: see docs/gi_tests.md.
constexpr uint32_t kDynamicSize = 32;
constexpr uint32_t kDynamicFrames = 1000;
constexpr uint32_t kDynamicSettle = 60; // the first frames build up from black
constexpr double kMaxDynamicStepRelMse = 0.05;

TEST_P(DynamicStress, AtriumDaySunSweepStaysFiniteWithBoundedChangeFor1000Frames) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = scene::loadScene("atrium_day");
    ASSERT_FALSE(scene.animation.empty());
    FrameHarness h(device(), shaders(), scene, {.width = kDynamicSize, .height = kDynamicSize});
    scene::Scene posed = scene;
    image::Image previous;
    double maxStep = 0.0, sumStep = 0.0;
    uint32_t steps = 0, maxStepFrame = 0;
    for (uint32_t f = 0; f < kDynamicFrames; ++f) {
        scene::animateScene(posed, f);
        h.renderer().applyScene(posed);
        h.render();
        image::Image hdr = h.hdr();
        ASSERT_EQ(measure::countNonFinite(hdr).total(), 0u) << "frame " << f;
        if (f >= kDynamicSettle) {
            const double step = measure::relMse(previous, hdr);
            sumStep += step;
            ++steps;
            if (step > maxStep) {
                maxStep = step;
                maxStepFrame = f;
            }
        }
        if ((f + 1) % kCheckEvery == 0) {
            const ProbeHealth health = probeHealth(device(), h);
            EXPECT_GT(health.validProbes, 0u);
            EXPECT_EQ(health.nonFiniteHistory, 0u) << "frame " << f;
            EXPECT_EQ(health.nonFiniteIrradiance, 0u) << "frame " << f;
            EXPECT_EQ(health.nonFiniteScreen, 0u) << "frame " << f;
        }
        previous = std::move(hdr);
    }
    std::printf(
        "atrium_day %ux%u, %u frames: frame-to-frame relMSE from frame %u: mean %.3g, max %.3g (frame %u)\n",
        kDynamicSize, kDynamicSize, kDynamicFrames, kDynamicSettle, sumStep / std::max(steps, 1u), maxStep,
        maxStepFrame);
    EXPECT_LT(maxStep, kMaxDynamicStepRelMse) << "frame " << maxStepFrame;
}

LUMINA_INSTANTIATE_GPU_TEST(DynamicStress);

} // namespace
} // namespace lumina::test
