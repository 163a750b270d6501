// Keyframe interpolation against values worked out by hand: STEP, LINEAR, CUBICSPLINE (glTF's
// Hermite form) and slerp, with the ends held.
#include "gi/scene/keyframes.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

Keyframes<float> scalarTrack(Interpolation interpolation, std::vector<double> times,
                             std::vector<float> values) {
    Keyframes<float> track;
    track.interpolation = interpolation;
    track.times = std::move(times);
    track.values = std::move(values);
    return track;
}

TEST(Keyframes, StepHoldsEachKeyUntilTheNext) {
    const Keyframes<float> track = scalarTrack(Interpolation::Step, {1.0, 2.0, 4.0}, {10.0f, 20.0f, 40.0f});
    EXPECT_EQ(sample(track, 0.0), 10.0f); // before the first key: the first value
    EXPECT_EQ(sample(track, 1.0), 10.0f);
    EXPECT_EQ(sample(track, 1.999), 10.0f);
    EXPECT_EQ(sample(track, 2.0), 20.0f);
    EXPECT_EQ(sample(track, 3.9), 20.0f);
    EXPECT_EQ(sample(track, 4.0), 40.0f);
    EXPECT_EQ(sample(track, 100.0), 40.0f); // after the last key: the last value
}

TEST(Keyframes, StepKeyHoldsAtItsFrameDespiteRounding) {
    // A key written for frame 7 at 60 fps, sampled a hair early (another rounding of 7/60).
    const Keyframes<float> track = scalarTrack(Interpolation::Step, {0.0, 7.0 / 60.0}, {0.0f, 1.0f});
    EXPECT_EQ(sample(track, std::nextafter(7.0 / 60.0, 0.0)), 1.0f);
    EXPECT_EQ(sample(track, 6.0 / 60.0), 0.0f);
}

TEST(Keyframes, LinearMixesNeighbours) {
    const Keyframes<float> track = scalarTrack(Interpolation::Linear, {0.0, 2.0, 3.0}, {1.0f, 5.0f, -1.0f});
    EXPECT_FLOAT_EQ(sample(track, 0.5), 2.0f); // 1 + (5 - 1) / 4
    EXPECT_FLOAT_EQ(sample(track, 2.0), 5.0f);
    EXPECT_FLOAT_EQ(sample(track, 2.25), 3.5f); // 5 - 6 / 4
    EXPECT_FLOAT_EQ(sample(track, 7.0), -1.0f);

    Keyframes<glm::vec3> vectors;
    vectors.times = {1.0, 3.0};
    vectors.values = {glm::vec3(0.0f, 2.0f, 4.0f), glm::vec3(4.0f, 2.0f, 0.0f)};
    const glm::vec3 middle = sample(vectors, 2.5);
    EXPECT_FLOAT_EQ(middle.x, 3.0f);
    EXPECT_FLOAT_EQ(middle.y, 2.0f);
    EXPECT_FLOAT_EQ(middle.z, 1.0f);
}

TEST(Keyframes, CubicSplineFollowsGltfsHermiteForm) {
    // Keys at t = 1 and 3 (duration 2): value 0, out-tangent 1; in-tangent -2, value 4.
    // p(u) = (2u^3 - 3u^2 + 1) 0 + (u^3 - 2u^2 + u) 2 * 1 + (-2u^3 + 3u^2) 4 + (u^3 - u^2) 2 * (-2).
    // At u = 0.5: 0 + 0.125 * 2 + 0.5 * 4 + (-0.125) * (-4) = 0.25 + 2 + 0.5 = 2.75.
    // At u = 0.25: (0.015625 - 0.125 + 0.25) 2 + (-0.03125 + 0.1875) 4 + (0.015625 - 0.0625)(-4)
    //            = 0.28125 + 0.625 + 0.1875 = 1.09375.
    const Keyframes<float> track =
        scalarTrack(Interpolation::CubicSpline, {1.0, 3.0}, {9.0f, 0.0f, 1.0f, -2.0f, 4.0f, 9.0f});
    EXPECT_FLOAT_EQ(sample(track, 2.0), 2.75f);
    EXPECT_FLOAT_EQ(sample(track, 1.5), 1.09375f);
    EXPECT_FLOAT_EQ(sample(track, 1.0), 0.0f); // the key values, not the tangents
    EXPECT_FLOAT_EQ(sample(track, 3.0), 4.0f);
    EXPECT_FLOAT_EQ(sample(track, 0.0), 0.0f);
    EXPECT_FLOAT_EQ(sample(track, 5.0), 4.0f);
}

TEST(Keyframes, SlerpTurnsAtConstantRateAlongTheShorterArc) {
    Keyframes<glm::quat> track;
    track.times = {0.0, 1.0};
    const glm::vec3 y(0.0f, 1.0f, 0.0f);
    track.values = {glm::angleAxis(0.0f, y), glm::angleAxis(glm::radians(90.0f), y)};
    for (const float t : {0.25f, 0.5f, 0.75f}) {
        const glm::quat q = sample(track, double(t));
        EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
        // A rotation about +y by 90 t degrees: cos(45 t deg), sin(45 t deg) along y.
        EXPECT_NEAR(q.w, std::cos(glm::radians(45.0f * t)), 1e-6f);
        EXPECT_NEAR(q.y, std::sin(glm::radians(45.0f * t)), 1e-6f);
        EXPECT_NEAR(q.x, 0.0f, 1e-6f);
        EXPECT_NEAR(q.z, 0.0f, 1e-6f);
    }
    // The same end stored as -q: still a 90 degree turn, not the 270 degree way round.
    track.values[1] = -track.values[1];
    const glm::quat half = sample(track, 0.5);
    EXPECT_NEAR(std::abs(half.w), std::cos(glm::radians(22.5f)), 1e-6f);
    // Slerp at 0.5 between 0 and 160 degrees is 80 degrees, where a normalised lerp would not
    // keep a constant rate (checked at t = 0.25: 40 degrees).
    const glm::quat a = glm::angleAxis(0.0f, y), b = glm::angleAxis(glm::radians(160.0f), y);
    EXPECT_NEAR(2.0f * std::acos(slerpShortest(a, b, 0.25f).w), glm::radians(40.0f), 1e-5f);
}

TEST(Keyframes, CubicRotationsAreNormalised) {
    Keyframes<glm::quat> track;
    track.interpolation = Interpolation::CubicSpline;
    track.times = {0.0, 1.0};
    const glm::quat zero(0.0f, 0.0f, 0.0f, 0.0f);
    track.values = {zero,
                    glm::quat(1.0f, 0.0f, 0.0f, 0.0f),
                    zero,
                    zero,
                    glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f)),
                    zero};
    const glm::quat q = sample(track, 0.5);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    // Zero tangents: the Hermite weights at u = 0.5 are 0.5 and 0.5, so q is the normalised mean.
    const glm::quat mean = glm::normalize(glm::quat(1.0f, 0.0f, 0.0f, 0.0f) * 0.5f + track.values[4] * 0.5f);
    EXPECT_NEAR(q.w, mean.w, 1e-6f);
    EXPECT_NEAR(q.x, mean.x, 1e-6f);
}

} // namespace
} // namespace lumina::scene
