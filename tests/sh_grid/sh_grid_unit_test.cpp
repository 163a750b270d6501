// The SH grid's CPU halves (docs/sh_grid.md): texel solid angles, the grid's placement, the
// ringing window, the bake schedule's order and budget, grid files and settings errors.
#include "gi/sh_grid/sh_grid_file.h"
#include "gi/sh_grid/sh_grid_schedule.h"
#include "gi/sh_grid/sh_grid_settings.h"
#include "shaders/sh_grid/sh_grid_shared.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <set>

namespace lumina::gi {
namespace {

TEST(ShGridMath, TexelSolidAnglesCoverTheSphere) {
    for (uint32_t size : {1u, 8u, 33u}) {
        double sum = 0.0;
        for (uint32_t y = 0; y < size; ++y) {
            for (uint32_t x = 0; x < size; ++x) {
                sum += gpu::shCubeTexelSolidAngle(float(x), float(y), float(size));
            }
        }
        EXPECT_NEAR(6.0 * sum, 4.0 * std::numbers::pi, 1e-4) << size << " texels";
    }
    // A face's centre texel sees more of the sphere than its corner texel.
    EXPECT_GT(gpu::shCubeTexelSolidAngle(4, 4, 8), gpu::shCubeTexelSolidAngle(0, 0, 8));
}

TEST(ShGridLayout, ProbesSitAtCellCentresInsideTheBox) {
    ShGridSettings s;
    s.probesPerAxis = 4;
    const scene::Bounds box{glm::vec3(0.0f), glm::vec3(8.0f, 4.0f, 4.0f)};
    const ShGridLayout grid = fitShGrid(s, box);
    EXPECT_EQ(grid.counts, glm::uvec3(4, 2, 2));
    EXPECT_EQ(grid.spacing, glm::vec3(2.0f));
    EXPECT_EQ(grid.position(0), glm::vec3(1.0f));
    EXPECT_EQ(grid.position(grid.probes() - 1), glm::vec3(7.0f, 3.0f, 3.0f));
    EXPECT_EQ(grid.cell(5), glm::uvec3(1, 1, 0));
}

TEST(ShGridLayout, AFlatSceneStillGetsTwoLayers) {
    ShGridSettings s;
    s.probesPerAxis = 4;
    const ShGridLayout grid = fitShGrid(s, {glm::vec3(0.0f), glm::vec3(8.0f, 0.0f, 8.0f)});
    EXPECT_EQ(grid.counts, glm::uvec3(4, 2, 4));
    EXPECT_GT(grid.spacing.y, 0.0f);
}

TEST(ShGridSettings, BadValuesAreNamed) {
    const auto message = [](auto change) {
        ShGridSettings s;
        change(s);
        try {
            s.validate();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message([](ShGridSettings& s) { s.probesPerAxis = 1; }).find("probes per axis"),
              std::string::npos);
    EXPECT_NE(message([](ShGridSettings& s) { s.faceSize = 4; }).find("face size"), std::string::npos);
    EXPECT_NE(message([](ShGridSettings& s) { s.probesPerFrame = 0; }).find("probes per frame"),
              std::string::npos);
    EXPECT_NE(message([](ShGridSettings& s) { s.sweeps = 0; }).find("sweeps"), std::string::npos);
    EXPECT_NE(message([](ShGridSettings& s) { s.ringingWindow = 1.0f; }).find("ringing window"),
              std::string::npos);
    EXPECT_EQ(message([](ShGridSettings&) {}), "");
}

TEST(ShGridWindow, HannFactorsFallWithTheBand) {
    EXPECT_EQ(shGridWindow(0.0f), glm::vec2(1.0f));
    const glm::vec2 w = shGridWindow(4.0f);
    EXPECT_NEAR(w.x, 0.5 * (1.0 + std::cos(std::numbers::pi / 4.0)), 1e-6);
    EXPECT_NEAR(w.y, 0.5, 1e-6);
}

ShGridLayout cube(uint32_t n) {
    return {.origin = glm::vec3(0.5f), .spacing = glm::vec3(1.0f), .counts = glm::uvec3(n)};
}

TEST(ShGridSchedule, BakesEverySweepWithinTheBudgetThenNothing) {
    ShGridSchedule schedule(cube(2), 2);
    EXPECT_EQ(schedule.owedBakes(), 16u);
    std::vector<uint32_t> firstSweep;
    for (int frame = 0; frame < 2; ++frame) {
        const std::vector<uint32_t> batch = schedule.next(4);
        ASSERT_EQ(batch.size(), 4u);
        firstSweep.insert(firstSweep.end(), batch.begin(), batch.end());
    }
    // One sweep of all eight probes before any is baked twice.
    EXPECT_EQ(std::set<uint32_t>(firstSweep.begin(), firstSweep.end()).size(), 8u);
    EXPECT_EQ(schedule.next(100).size(), 8u);
    EXPECT_TRUE(schedule.idle());
    EXPECT_TRUE(schedule.next(4).empty()); // nothing changed: nothing baked
}

TEST(ShGridSchedule, ProbesNearAChangeGoFirstAndTheRestOweOneBake) {
    ShGridSchedule schedule(cube(4), 3);
    schedule.settle();
    // A change around probe (3, 3, 3) at (3.5, 3.5, 3.5).
    schedule.changed({glm::vec3(3.4f), glm::vec3(3.6f)}, 0.5f);
    EXPECT_EQ(schedule.dirtyProbes(), 1u);
    EXPECT_EQ(schedule.owedBakes(), 3u + 63u);
    // The dirty probe's first two sweeps are its alone (a batch never spans two sweeps).
    const std::vector<uint32_t> first = schedule.next(2);
    ASSERT_EQ(first, std::vector<uint32_t>{63u});
    EXPECT_EQ(schedule.dirtyProbes(), 0u);
    uint32_t frames = 1;
    while (!schedule.idle()) {
        schedule.next(2);
        ++frames;
    }
    EXPECT_EQ(frames, 34u); // 1 + 1, then the last sweep's 64 bakes 2 a frame
}

TEST(ShGridSchedule, EachSweepBeginsOnceAndNoBatchSpansTwo) {
    ShGridSchedule schedule(cube(2), 3); // 8 probes, 3 sweeps
    std::vector<bool> began;
    std::vector<size_t> sizes;
    while (!schedule.idle()) {
        sizes.push_back(schedule.next(3).size());
        began.push_back(schedule.batchBeganSweep());
    }
    // Each sweep: 3 + 3 + 2 probes, the third batch cut short rather than take the next sweep's.
    EXPECT_EQ(sizes, (std::vector<size_t>{3, 3, 2, 3, 3, 2, 3, 3, 2}));
    EXPECT_EQ(began, (std::vector<bool>{true, false, false, true, false, false, true, false, false}));
    EXPECT_TRUE(schedule.next(3).empty());
    EXPECT_FALSE(schedule.batchBeganSweep()); // nothing owed: no copy either

    // A change during a sweep begins another, which reads the grid as it stands.
    schedule.changed({glm::vec3(0.4f), glm::vec3(0.6f)}, 0.1f);
    ASSERT_EQ(schedule.next(1), std::vector<uint32_t>{0u});
    EXPECT_TRUE(schedule.batchBeganSweep());
    schedule.next(1);
    EXPECT_TRUE(schedule.batchBeganSweep()); // probe 0's second sweep
    schedule.changed({glm::vec3(1.4f), glm::vec3(1.6f)}, 0.1f);
    schedule.next(1);
    EXPECT_TRUE(schedule.batchBeganSweep()); // probe 7 now owes more than probe 0 does
}

TEST(ShGridFile, RoundTripsAndRejectsBadFiles) {
    const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "sh_grid_file_test";
    std::filesystem::create_directories(dir);
    ShGridFile grid{.layout = cube(2), .coefficients = {}};
    for (uint32_t i = 0; i < 8 * LUMINA_SH_GRID_COEFFICIENTS; ++i) {
        grid.coefficients.emplace_back(float(i), -0.5f * float(i), 1.0f / float(i + 1));
    }
    saveShGrid(dir / "grid.shgrid", grid);
    const ShGridFile back = loadShGrid(dir / "grid.shgrid");
    EXPECT_EQ(back.layout.counts, grid.layout.counts);
    EXPECT_EQ(back.layout.origin, grid.layout.origin);
    EXPECT_EQ(back.coefficients, grid.coefficients);
    EXPECT_NO_THROW(requireSameGrid(grid.layout, back.layout, "grid.shgrid"));
    EXPECT_THROW(requireSameGrid(cube(3), back.layout, "grid.shgrid"), std::invalid_argument);

    EXPECT_THROW(loadShGrid(dir / "missing.shgrid"), std::runtime_error);
    std::ofstream(dir / "text.shgrid") << "not a grid";
    EXPECT_THROW(loadShGrid(dir / "text.shgrid"), std::runtime_error);
    const auto size = std::filesystem::file_size(dir / "grid.shgrid");
    std::filesystem::copy_file(dir / "grid.shgrid", dir / "short.shgrid",
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(dir / "short.shgrid", size - 4);
    try {
        loadShGrid(dir / "short.shgrid");
        ADD_FAILURE() << "a truncated file loaded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace lumina::gi
