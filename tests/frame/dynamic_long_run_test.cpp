// The long run under change (docs/gi_tests.md, "Long run under change"): the atrium with its sun
// moving and a column sliding through the courtyard (tests/frame/data/atrium_sun_and_column.json,
// a 1,200-frame loop without a jump), for LUMINA_LONG_RUN_FRAMES frames (default 3,600, three
// loops). Labels `long` and `stress`: on lavapipe a frame costs over a second, so CI leaves it out
// (`ctest -LE long`); scripts/gpu/long_run.sh runs 100,000 frames on the lent GPU, where validation
// is switched off (LUMINA_LONG_RUN_VALIDATION=0) so that the run fits one call and the frame
// times are the renderer's own.
//
// What may never happen however long it runs: a non-finite value in the image or any probe
// history, a jump in the indirect term from one frame to the next, GPU memory that grows, frames
// that get slower. The last two compare loops (the same poses, so the same work): memory at the end
// of the second loop and of the last; the frame time's floor (the lowest loop median) over the
// first quarter of the loops after the first and over the last quarter. GPU clocks follow load and
// temperature and move a loop's median by 20 % and back (1.76 to 2.27 ms over the 100,000-frame
// run, docs/gi_tests.md); a leak of per-frame work raises the floor and never gives it back.
#include "gi/core/frame_context.h"
#include "gi/core/timing_table.h"
#include "gi/measure/metrics.h"
#include "gi/scene/scene_animation.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/frame/probe_health.h"
#include "tests/frame/step_stats.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kLoopFrames = 1200; // the scene's loop
constexpr uint32_t kDefaultFrames = 3 * kLoopFrames;
constexpr uint32_t kSettle = 60;                // the first frames build up from black
constexpr uint32_t kCheckProbesEvery = 500;     // probe histories read back (slow)
constexpr double kMaxIndirectStepRelMse = 0.02; // as dynamic_stress_test's sun sweep
// Allowed growth from the first quarter of the loops to the last: GPU memory not at all (nothing is
// allocated per frame once the scene is up), the frame time's floor by 10 %.
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
    // At least three loops' worth when set, so that the first and last quarters differ.
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

// Every how many frames the frame-to-frame change is measured (LUMINA_LONG_RUN_STEP_EVERY,
// default 1: every frame).
uint32_t longRunStepEvery() {
    const char* text = std::getenv("LUMINA_LONG_RUN_STEP_EVERY");
    const long every = text != nullptr ? std::strtol(text, nullptr, 10) : 1;
    return every >= 1 && every <= 1000 ? uint32_t(every) : 1u;
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
    std::vector<gi::PassTiming> passes; // median per pass over the loop
};

// The passes whose median moved by more than 5 % and 0.01 ms from loop `a` to loop `b`.
void printPassChanges(const LoopFigures& a, const LoopFigures& b) {
    for (const gi::PassTiming& later : b.passes) {
        const auto earlier = std::ranges::find(a.passes, later.name, &gi::PassTiming::name);
        const double before = earlier == a.passes.end() ? 0.0 : earlier->medianMs;
        if (std::abs(later.medianMs - before) > std::max(0.01, 0.05 * before)) {
            std::printf("  %-44s %8.4f -> %8.4f ms (ran %u -> %u frames)\n", later.name.c_str(), before,
                        later.medianMs, earlier == a.passes.end() ? 0u : earlier->frames, later.frames);
        }
    }
}

class DynamicLongRun : public GpuTestFixture, public ::testing::WithParamInterface<rhi::Api> {
protected:
    void SetUp() override { openDevice(GetParam(), longRunValidation()); }
};

TEST_P(DynamicLongRun, SunAndColumnStayFiniteBoundedAndSteady) {
    LUMINA_REQUIRE_KERNELS();
    const uint32_t frames = longRunFrames();
    const uint32_t stepEvery = longRunStepEvery();
    const scene::Scene scene = scene::loadScene(sceneFile().string());
    ASSERT_EQ(scene.animation.animatedLights().size(), 1u);
    ASSERT_EQ(scene.animation.animatedInstances().size(), 1u);
    FrameHarness h(device(), shaders(), scene, {.width = kSize, .height = kSize});
    scene::Scene posed = scene;

    image::Image previousIndirect;
    StepStats indirectSteps;
    std::vector<double> loopCpuMs;
    std::vector<LoopFigures> loops;
    // Frames recorded here rather than by h.render(), so that each loop gets its own per-pass
    // table: a growth shows which pass grew.
    rhi::CommandListHandle list = device().createCommandList();
    rhi::IQueue& queue = device().queue(list->queueType());
    gi::TimingTable loopTable;
    for (uint32_t f = 0; f < frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        scene::animateScene(posed, f);
        h.renderer().applyScene(posed);
        list->begin();
        gi::FrameContext frame(h.pipelines(), *list, f);
        h.renderer().render(frame);
        list->end();
        queue.waitForValue(queue.submit(*list));
        loopTable.addFrame(list->timerResults(), frame.skipped());
        loopCpuMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());

        // The indirect term is read back on the frames that end a measured step: every frame by
        // default, every stepEvery-th pair of frames on the lent GPU (readbacks cost more than a
        // frame there). A non-finite value in any history buffer stays until the probe check.
        const bool stepEnds = f % stepEvery == 0;
        const bool stepStarts = (f + 1) % stepEvery == 0;
        if (stepEnds || stepStarts) {
            image::Image indirect = h.indirect();
            ASSERT_EQ(measure::countNonFinite(indirect).total(), 0u) << "frame " << f;
            if (stepEnds && f >= kSettle && !previousIndirect.channelNames().empty()) {
                indirectSteps.add(measure::relMse(previousIndirect, indirect), f);
            }
            previousIndirect = stepStarts ? std::move(indirect) : image::Image();
        }

        if ((f + 1) % kCheckProbesEvery == 0 || f + 1 == frames) {
            ASSERT_EQ(measure::countNonFinite(h.hdr()).total(), 0u) << "frame " << f;
            const ProbeHealth health = probeHealth(device(), h);
            EXPECT_GT(health.validProbes, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteHistory, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteIrradiance, 0u) << "frame " << f;
            ASSERT_EQ(health.nonFiniteScreen, 0u) << "frame " << f;
        }
        if ((f + 1) % kLoopFrames == 0) {
            loops.push_back({loopTable.medianFrameMs(), gi::median(loopCpuMs),
                             device().allocatedMemoryBytes(), loopTable.passes()});
            loopTable = gi::TimingTable();
            loopCpuMs.clear();
            const LoopFigures& l = loops.back();
            std::printf(
                "loop %zu (frames %u-%u): GPU %.3f ms, CPU %.3f ms a frame (medians), GPU memory %.1f MiB, "
                "indirect step so far mean %.3g max %.3g\n",
                loops.size(), f + 1 - kLoopFrames, f, l.medianGpuMs, l.medianCpuMs,
                double(l.memoryBytes) / (1024.0 * 1024.0), indirectSteps.mean(), indirectSteps.max);
            std::fflush(stdout);
        }
    }
    ASSERT_GE(loops.size(), 3u);
    const LoopFigures& second = loops[1];
    const LoopFigures& last = loops.back();
    // The floors: the lowest loop median over loops 2 .. 1 + quarter and over the last quarter.
    const size_t quarter = std::max<size_t>(1, (loops.size() - 1) / 4);
    const auto floorOf = [&](size_t first, double LoopFigures::*field) {
        double lowest = loops[first].*field;
        for (size_t i = first; i < first + quarter; ++i) {
            lowest = std::min(lowest, loops[i].*field);
        }
        return lowest;
    };
    const double earlyGpu = floorOf(1, &LoopFigures::medianGpuMs),
                 lateGpu = floorOf(loops.size() - quarter, &LoopFigures::medianGpuMs);
    const double earlyCpu = floorOf(1, &LoopFigures::medianCpuMs),
                 lateCpu = floorOf(loops.size() - quarter, &LoopFigures::medianCpuMs);
    std::printf(
        "%u frames at %ux%u (%s, validation %s): indirect frame-to-frame relMSE (%u steps) mean %.3g, max "
        "%.3g "
        "(frame %u); %zu loops, the lowest loop median over the first and the last %zu: GPU %.3f -> %.3f ms, "
        "CPU %.3f -> %.3f ms; memory after loop 2 and at the end %.1f -> %.1f MiB\n",
        frames, kSize, kSize, std::string(rhi::apiName(GetParam())).c_str(),
        longRunValidation() ? "on" : "off", indirectSteps.count, indirectSteps.mean(), indirectSteps.max,
        indirectSteps.maxFrame, loops.size(), quarter, earlyGpu, lateGpu, earlyCpu, lateCpu,
        double(second.memoryBytes) / (1024.0 * 1024.0), double(last.memoryBytes) / (1024.0 * 1024.0));
    std::printf("passes that changed from loop 2 to loop %zu:\n", loops.size());
    printPassChanges(second, last);
    EXPECT_LT(indirectSteps.max, kMaxIndirectStepRelMse) << "frame " << indirectSteps.maxFrame;
    EXPECT_LE(last.memoryBytes, second.memoryBytes) << "GPU memory grew";
    EXPECT_LE(lateGpu, earlyGpu * kMaxFrameTimeGrowth) << "GPU frame time grew";
    EXPECT_LE(lateCpu, earlyCpu * kMaxCpuTimeGrowth) << "CPU frame time grew";
}

INSTANTIATE_TEST_SUITE_P(Backends, DynamicLongRun, ::testing::ValuesIn(::lumina::app::compiledApis()),
                         ::lumina::test::apiName);

} // namespace
} // namespace lumina::test
