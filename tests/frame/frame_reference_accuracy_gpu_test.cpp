// Lumen's accuracy against stored path-traced references (docs/gi_tests.md, docs/gi.md), after
// convergence (surface cache converged, then 48 frames, as `lumina render` runs), at 128 x 128,
// medium preset: per scene, the final image's relMSE at most a given fraction of the direct-only
// image's (what a user gets with no GI) against the same reference, and its mean radiance within a
// given fraction of the reference's. frame_presets_accuracy_gpu_test.cpp compares the presets.
// The references are stored (tests/frame/data/<scene>_128x128.exr), at pixel centres: 65,536
// samples per pixel made on the lent GPU (the Cornell boxes' and the open-top box's own noise below
// 3e-4 relMSE; the two-room scenes', mean relative standard error 0.010 and 0.025).
//
// Regenerate after a change to the scenes or the path tracer (scripts/gpu/stored_references.sh):
//   lumina reference SCENE --size 128x128 --spp 65536 --pixel-centres --out
//   tests/frame/data/SCENE_128x128.exr
// and for a posed scene, SCENE@F, with --animation-frame F into SCENE_frameF_128x128.exr.
#include "tests/frame/stored_reference.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <ostream>
#include <string>

namespace lumina::test {
namespace {

struct SceneGoal {
    const char* scene;
    double relMseFraction; // lumen's relMSE / direct-only's, at most
    double meanTolerance;  // |lumen's mean / the reference's - 1|, at most
    const char* preset = "medium";
};

void PrintTo(const SceneGoal& goal, std::ostream* out) {
    *out << goal.scene << " " << goal.preset;
}

class FrameVsStoredReferenceGpu : public GpuTestFixture,
                                  public ::testing::WithParamInterface<std::tuple<rhi::Api, SceneGoal>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

TEST_P(FrameVsStoredReferenceGpu, LumenMeetsItsSceneGoal) {
    LUMINA_REQUIRE_KERNELS();
    const SceneGoal& goal = std::get<1>(GetParam());
    const StoredReferenceFigures f =
        measureAgainstStoredReference(device(), shaders(), goal.scene, goal.preset);
    ASSERT_TRUE(f.referenceSized) << goal.scene << ": stored reference is not 128x128";
    EXPECT_TRUE(f.converged) << goal.scene << ": surface cache not converged after " << f.frames << " frames";
    EXPECT_EQ(f.nonFinitePixels, 0u);
    EXPECT_LE(f.lumenRelMse, goal.relMseFraction * f.directRelMse);
    EXPECT_NEAR(f.meanRatio, 1.0, goal.meanTolerance);
}

std::string goalName(const ::testing::TestParamInfo<std::tuple<rhi::Api, SceneGoal>>& info) {
    const SceneGoal& goal = std::get<1>(info.param);
    const std::string preset = goal.preset == std::string("medium") ? "" : std::string("_") + goal.preset;
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + poseName(goal.scene) + preset;
}

// The goal (issue 26): relMSE at most a twentieth of direct-only's in the Cornell boxes and the
// two-room scenes, a tenth in the open-top box, the mean within 3 %. Where a scene does not meet
// it yet, the bound is the figure measured on lavapipe (128x128, medium, commit of issue 26) with
// a margin, and docs/gi.md says what is missing. Measured: relMSE / direct-only's, mean ratio.
const SceneGoal kSceneGoals[] = {
    // 0.035, 1.017 since the near field covers the whole ray (docs/gi.md, energy 41.); 0.036, 1.021
    // since the outlier clamp's ceiling comes from the texels' unclamped means
    // (docs/gi.md, energy 40.: 1.036 with the whole mean, share 1); 0.061, 1.014 since the screen
    // probes' rays start on their probe's line (energy 22.); 0.052, 1.009 before; 0.047 before the
    // Cornell blocks became solids. The goal since energy 40.
    {.scene = "cornell_box", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // 0.022, 0.978 since energy 41.; 0.022, 1.002 since energy 40. (0.038, 1.014 before it; 0.034, 1.006
    // before energy 22.).
    {.scene = "cornell_box_point", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // 0.045, 0.985 since energy 41.; 0.048, 0.974 since energy 40., the goal. Before: 0.055, 0.960 since the
    // sun's shadow stopped
    // leaking at the foot of a wall (docs/deferred.md, "Shadows"); 0.069, 0.962 before that (0.072,
    // 0.959 before energy 22.); the mean's goal not met since rays no longer read faces that face
    // along them (docs/gi.md, energy 10.): 1.014 before, where rays passing the opening's rim read
    // the sunlit outside and made up for the sky the rim's shell hides.
    {.scene = "open_top_box", .relMseFraction = 0.1, .meanTolerance = 0.03},
    // 0.041, 1.016 since energy 46.; 0.043, 1.013 since energy 41.; 0.046, 1.006 since energy 40.,
    // the goal. Before, against the 65,536-spp reference: 0.090, 1.036 (the earlier one, made on
    // lavapipe, had noise of its own, relMSE 0.007 against it:
    // 0.111, 1.022 then; 0.110, 1.036 before energy 22., the east room too bright; 0.129, 1.086
    // with the radiosity probes lifted two voxels, 16.).
    {.scene = "two_rooms", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // 0.019, 0.990 since energy 46.; 0.022, 0.983 since energy 41.; 0.023, 0.974 since energy 40.
    // (0.029, 0.999 before) against the 65,536-spp reference: the goal. Against the earlier
    // reference made on lavapipe, whose own noise (relMSE 0.041 against the new one: the sun's
    // patch is found by few paths) was most of the figure: 0.197, 0.988
    // since the sun's shadow stopped leaking at the foot of a wall (docs/deferred.md, "Shadows");
    // 0.673, 0.999 before (1.283, 1.458 before energy 9.-11.), 0.59 of the 0.68 five floor pixels
    // the sun lit through the wall.
    {.scene = "sunlit_rooms", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // 0.013, 0.999 since adaptive screen probes (docs/gi.md, energy 46.): a probe on the jamb no cell
    // centre saw. 0.028, 0.968 since energy 41.: the mean 3.2 % dark, the test failed. At 128^2 high's
    // probes every 6 px were too few (energy 41.: every 4 px, 1.001 on the H200; 0.999 there at
    // 256^2). Before: 0.034, 1.016 against the 65,536-spp reference: the goal (relMSE 0.00735 against
    // medium's
    // 0.00620, so FramePresetsGpu finds high less accurate than medium). Against the earlier
    // reference made on lavapipe: 0.219, 1.042 since the sun's shadow stopped leaking at the foot
    // of a wall (direct-only's 0.224); before: 0.613, 1.074 (direct-only's error 0.434 at high,
    // with its finer shadow map): the high preset's 9 cm radiosity blocks under the zero-thickness
    // ceiling hold no texel with clearance, and their probes were pushed up through it to read the
    // sky and the sunlit roof (0.662, 1.185; docs/gi.md, energy 18.).
    {.scene = "sunlit_rooms", .relMseFraction = 0.05, .meanTolerance = 0.03, .preset = "high"},
    // The other built-in scenes (their references made on the lent GPU by
    // scripts/gpu/stored_references.sh). Issue 26 asks the mean within 3 % of each; the relMSE
    // bound is the figure measured on lavapipe with a margin, so that a change that loses accuracy
    // fails. Measured (relMSE / direct-only's, mean ratio):
    // 0.035, 1.017 since energy 41.; 0.036, 1.021 since energy 40. (0.034, 1.012 before): the Cornell box
    // with its block as an
    // instance of its own (the moving box at its first pose; the same reference, stored_reference.h).
    {.scene = "cornell_box_moving", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // 0.053, 0.995 since energy 47. (slots shared evenly: it wants 157 for 64); 0.054, 0.995 since
    // energy 46.; 0.054, 0.993 since energy 41. (0.052, 0.993 before).
    {.scene = "two_cylinder_engine", .relMseFraction = 0.06, .meanTolerance = 0.03},
    // 0.077, 1.008 since energy 47. (adaptive slots shared evenly: it wants 387 for 64); 0.106,
    // 1.016 since energy 46.; 0.113, 1.013 since energy 41. (0.105, 0.987 before).
    {.scene = "atrium_day", .relMseFraction = 0.09, .meanTolerance = 0.03},
    // 0.147, 0.989 since energy 47.; 0.167, 0.993 since energy 46.; 0.171, 0.991 since energy 41.
    // (0.191, 1.011 before; on the H200 at 256^2, 1.027 then, 1.007 at 41.: docs/gi.md says why the
    // image size matters).
    {.scene = "atrium", .relMseFraction = 0.17, .meanTolerance = 0.03},
    // door with the door open (frame 240 of its loop: swung 90 degrees into the dark room), whose
    // light all comes through the doorway. Shut (its first pose), the dark room takes only what
    // passes the door's 1 cm gaps, finer than the SDFs and cards resolve: FrameClosedDoorGpu holds
    // that lumen adds no light through the door, and docs/gi.md says what the shut door misses.
    // Measured: 0.017, 1.013 since adaptive screen probes (docs/gi.md, energy 46.): the goal. Before:
    // 0.070, 1.018 (on the H200 at 128^2: 0.070, 1.017): 90 % of the error (at 256^2 on the H200)
    // was a 6 cm strip of wall in the corner between the wall and the open door, on which no probe
    // landed (energy 45.).
    {.scene = "door@240", .relMseFraction = 0.05, .meanTolerance = 0.03},
    // city (label long: on lavapipe at 128^2 the low preset converges in 466 frames, 18 minutes;
    // medium ran over 30) at medium and low. Lavapipe, low: relMSE 2.044 times direct-only's, mean
    // 1.006. On the H200 at 128^2: 2.19 and 2.16, means 1.018 and 1.006. Its error lies where the
    // sun's shadow map misses the windows' recesses (docs/gi.md, energy 30.).
    {.scene = "city", .relMseFraction = 2.5, .meanTolerance = 0.03},
    {.scene = "city", .relMseFraction = 2.5, .meanTolerance = 0.03, .preset = "low"},
};

INSTANTIATE_TEST_SUITE_P(Scenes, FrameVsStoredReferenceGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::ValuesIn(kSceneGoals)),
                         goalName);

} // namespace
} // namespace lumina::test
