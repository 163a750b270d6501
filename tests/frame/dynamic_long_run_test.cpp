// The long run under change (docs/gi_tests.md, "Long run under change"): the atrium with its sun
// moving and a column sliding through the courtyard (tests/frame/data/atrium_sun_and_column.json,
// a 1,200-frame loop without a jump), for LUMINA_LONG_RUN_FRAMES frames (default 2,400, two
// loops). Labels `long` and `stress`: on lavapipe a frame costs over a second, so CI leaves it out
// (`ctest -LE long`); scripts/gpu/long_run.sh runs 100,000 frames on the lent GPU, where validation
// is switched off (LUMINA_LONG_RUN_VALIDATION=0) so that the run fits one call and the frame
// times are the renderer's own.
//
// What may never happen however long it runs: a non-finite value in the image or any probe
// history, a jump in the indirect term from one frame to the next, GPU memory that grows, frames
// that get slower. The last two compare the second loop with the last one: the same poses, so the
// same work.
#include "gi/measure/metrics.h"
#include "gi/scene/scene_animation.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/frame/probe_health.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kLoopFrames = 1200; // the scene's loop
constexpr uint32_t kDefaultFrames = 2 * kLoopFrames;
constexpr uint32_t kSettle = 60;                // the first frames build up from black
constexpr uint32_t kCheckProbesEvery = 500;     // probe histories read back (slow)
constexpr double kMaxIndirectStepRelMse = 0.02; // as dynamic_stress_test's sun sweep
// Allowed growth from the second loop to the last: GPU memory not at all (nothing is allocated
// per frame once the scene is up), the median frame time by 10 % (clocks and other tenants of a
// shared GPU move it a little; a leak of per-frame work grows it without bound).
constexpr double kMaxFrameTimeGrowth = 1.10;
// The CPU side (recording, scene updates, the readback) shares the machine with whatever else runs
// there, so it gets more slack; a per-frame leak of CPU work still grows past it over a long run.
constexpr double kMaxCpuTimeGrowth = 1.5;

uint32_t longRunFrames() {
    const char* text = std::getenv("LUMINA_LONG_RUN_FRAMES");
    if (text == nullptr || *text == '\0') {
        return kDefaultFrames;
    }
    const long frames = std::strtol(text, nullptr, 10);
    // At least three loops' worth when set, so that "second loop" and "last loop" differ.
    return frames >= long(3 * kLoopFrames) ? uint32_t(frames) : kDefaultFrames;
}

// The scene file: under $LUMINA_SOURCE_DIR when set (the lent GPU runs a copy of the tree in
// another place), else in the tree this was built from.
std::filesystem::path sceneFile() {
    const char* source = std::getenv("LUMINA_SOURCE_DIR");
    const std::filesystem::path data = source != nullptr && *source != '\0'
                                           ? std::filesystem::path(source) / "tests/frame/data"
                                           : std::filesystem::path(LUMINA_FRAME_TEST_DATA_DIR);
    return data / "atrium_sun_and_column.json";
}

bool longRunValidation() {
    const char* text = std::getenv("LUMINA_LONG_RUN_VALIDATION");
    return text == nullptr || std::string(text) != "0";
}

// Median of the frame times of one loop, and the GPU memory at its end.
struct LoopFigures {
    double medianGpuMs = 0.0;
    double medianCpuMs = 0.0;
    uint64_t memoryBytes = 0;
};

class DynamicLongRun : public GpuTestFixture, public ::testing::WithParamInterface<rhi::Api> {
protected:
    void SetUp() override { openDevice(GetParam(), longRunValidation()); }
};

TEST_P(DynamicLongRun, SunAndColumnStayFiniteBoundedAndSteady) {
    LUMINA_REQUIRE_KERNELS();
    const uint32_t frames = longRunFrames();
    const scene::Scene scene = scene::loadScene(sceneFile().string());
    ASSERT_EQ(scene.animation.animatedLights().size(), 1u);
    ASSERT_EQ(scene.animation.animatedInstances().size(), 1u);
    FrameHarness h(device(), shaders(), scene, {.width = kSize, .height = kSize});
    scene::Scene posed = scene;

    image::Image previousIndirect;
    double maxIndirectStep = 0.0, sumIndirectStep = 0.0;
    uint32_t maxStepFrame = 0, steps = 0;
    std::vector<double> loopGpuMs, loopCpuMs;
    std::vector<LoopFigures> loops;
    for (uint32_t f = 0; f < frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        scene::animateScene(posed, f);
        h.renderer().applyScene(posed);
        h.render();
        loopCpuMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        loopGpuMs.push_back(h.timings().lastFrameMs());

        image::Image indirect = h.indirect();
        ASSERT_EQ(measure::countNonFinite(indirect).total(), 0u) << "frame " << f;
        if (f >= kSettle) {
            const double step = measure::relMse(previousIndirect, indirect);
            sumIndirectStep += step;
            ++steps;
            if (step > maxIndirectStep) {
                maxIndirectStep = step;
                maxStepFrame = f;
            }
        }
        previousIndirect = std::move(indirect);

        if ((f + 1) % kCheckProbesEvery == 0 || f + 1 == frames) {
            ASSERT_EQ(measure::countNonFinite(h.hdr()).total(), 0u) << "frame " << f;
            const ProbeHealth health = probeHealth(device(), h);
            EXPECT_GT(health.validProbes, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteHistory, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteIrradiance, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteScreen, 0u) << "frame " << f;
        }
        if ((f + 1) % kLoopFrames == 0) {
            loops.push_back({gi::median(loopGpuMs), gi::median(loopCpuMs), device().allocatedMemoryBytes()});
            loopGpuMs.clear();
            loopCpuMs.clear();
            const LoopFigures& l = loops.back();
            std::printf(
                "loop %zu (frames %u-%u): GPU %.3f ms, CPU %.3f ms a frame (medians), GPU memory %.1f MiB, "
                "indirect step so far mean %.3g max %.3g\n",
                loops.size(), f + 1 - kLoopFrames, f, l.medianGpuMs, l.medianCpuMs,
                double(l.memoryBytes) / (1024.0 * 1024.0), steps ? sumIndirectStep / steps : 0.0,
                maxIndirectStep);
            std::fflush(stdout);
        }
    }
    ASSERT_GE(loops.size(), 2u);
    const LoopFigures& second = loops[1];
    const LoopFigures& last = loops.back();
    std::printf(
        "%u frames at %ux%u (%s, validation %s): indirect frame-to-frame relMSE mean %.3g, max %.3g "
        "(frame %u); loop 2 against loop %zu: GPU %.3f -> %.3f ms, CPU %.3f -> %.3f ms, memory %.1f -> "
        "%.1f MiB\n",
        frames, kSize, kSize, std::string(rhi::apiName(GetParam())).c_str(),
        longRunValidation() ? "on" : "off", steps ? sumIndirectStep / steps : 0.0, maxIndirectStep,
        maxStepFrame, loops.size(), second.medianGpuMs, last.medianGpuMs, second.medianCpuMs,
        last.medianCpuMs, double(second.memoryBytes) / (1024.0 * 1024.0),
        double(last.memoryBytes) / (1024.0 * 1024.0));
    EXPECT_LT(maxIndirectStep, kMaxIndirectStepRelMse) << "frame " << maxStepFrame;
    EXPECT_LE(last.memoryBytes, second.memoryBytes) << "GPU memory grew";
    EXPECT_LE(last.medianGpuMs, second.medianGpuMs * kMaxFrameTimeGrowth) << "GPU frame time grew";
    EXPECT_LE(last.medianCpuMs, second.medianCpuMs * kMaxCpuTimeGrowth) << "CPU frame time grew";
}

INSTANTIATE_TEST_SUITE_P(Backends, DynamicLongRun, ::testing::ValuesIn(::lumina::app::compiledApis()),
                         ::lumina::test::apiName);

} // namespace
} // namespace lumina::test
