// --technique auto's rule and its cache key (gi/bench/auto_technique.h).
#include "gi/bench/auto_technique.h"
#include "gi/scene/scene_loader.h"

#include <gtest/gtest.h>

namespace lumina::gi {
namespace {

TEST(AutoTechnique, CheapestCandidateUnderTheBudget) {
    const std::vector<AutoCandidate> candidates = {{"direct", "low", 1.0, 0.30},
                                                   {"sh-grid", "low", 5.0, 0.10},
                                                   {"lumen", "low", 3.0, 0.12},
                                                   {"lumen", "high", 9.0, 0.05}};
    EXPECT_EQ(cheapestUnder(candidates, 0.5), 0u);
    EXPECT_EQ(cheapestUnder(candidates, 0.12), 2u); // lumen low: cheaper than sh-grid, at the budget
    EXPECT_EQ(cheapestUnder(candidates, 0.11), 1u);
    EXPECT_EQ(cheapestUnder(candidates, 0.05), 3u);
    EXPECT_FALSE(cheapestUnder(candidates, 0.01).has_value());
    EXPECT_FALSE(cheapestUnder({}, 1.0).has_value());
}

TEST(AutoTechnique, CacheKeyFollowsSceneAndCalibration) {
    const scene::Scene scene = scene::loadScene("cornell_box_point");
    const CalibrationRequest request;
    const std::filesystem::path path = calibrationPath("cache", scene, request);
    EXPECT_EQ(path, calibrationPath("cache", scene::loadScene("cornell_box_point"), request));
    EXPECT_NE(path, calibrationPath("cache", scene::loadScene("cornell_box"), request));
    CalibrationRequest other = request;
    other.width += 1;
    EXPECT_NE(path, calibrationPath("cache", scene, other));
    other = request;
    other.frames += 1;
    EXPECT_NE(path, calibrationPath("cache", scene, other));
    other = request;
    other.presets = {"low"};
    EXPECT_NE(path, calibrationPath("cache", scene, other));
    scene::Scene moved = scene;
    moved.camera.position.x += 0.01f;
    EXPECT_NE(path, calibrationPath("cache", moved, request));
}

} // namespace
} // namespace lumina::gi
