#include "gi/scene/keyframes.h"

#include <algorithm>
#include <cmath>

namespace lumina::scene {

namespace {

// Where `time` falls: between key `key` and key + 1 at fraction `u` in [0, 1]; key is the last
// key (u = 0) after the end, the first key before the start.
struct Segment {
    size_t key = 0;
    float u = 0.0f;
    double duration = 0.0; // seconds from key to key + 1; 0 at either end
};

Segment findSegment(const std::vector<double>& times, double time) {
    const auto after = std::upper_bound(times.begin(), times.end(), time + kKeyTimeTolerance);
    if (after == times.begin()) {
        return {};
    }
    const auto key = size_t(after - times.begin()) - 1;
    if (after == times.end()) {
        return {key, 0.0f, 0.0};
    }
    const double duration = times[key + 1] - times[key];
    return {key, float(std::clamp((time - times[key]) / duration, 0.0, 1.0)), duration};
}

// glTF Appendix C: the cubic Hermite spline from key k to k + 1, tangents scaled by the
// segment's duration.
template <typename T>
T hermite(const Keyframes<T>& track, const Segment& s) {
    const float u = s.u, u2 = u * u, u3 = u2 * u;
    const auto duration = float(s.duration);
    const T& value0 = track.values[3 * s.key + 1];
    const T& out0 = track.values[3 * s.key + 2];
    const T& in1 = track.values[3 * (s.key + 1)];
    const T& value1 = track.values[3 * (s.key + 1) + 1];
    return value0 * (2.0f * u3 - 3.0f * u2 + 1.0f) + out0 * (duration * (u3 - 2.0f * u2 + u)) +
           value1 * (-2.0f * u3 + 3.0f * u2) + in1 * (duration * (u3 - u2));
}

template <typename T>
T sampleMixed(const Keyframes<T>& track, double time) {
    const Segment s = findSegment(track.times, time);
    if (s.duration == 0.0 || track.interpolation == Interpolation::Step || s.u == 0.0f) {
        return track.keyValue(s.key);
    }
    if (track.interpolation == Interpolation::CubicSpline) {
        return hermite(track, s);
    }
    return track.keyValue(s.key) * (1.0f - s.u) + track.keyValue(s.key + 1) * s.u;
}

} // namespace

const char* interpolationName(Interpolation interpolation) {
    switch (interpolation) {
    case Interpolation::Step:
        return "STEP";
    case Interpolation::Linear:
        return "LINEAR";
    case Interpolation::CubicSpline:
        return "CUBICSPLINE";
    }
    return "unknown";
}

glm::quat slerpShortest(const glm::quat& a, const glm::quat& b, float t) {
    float cosAngle = glm::dot(a, b);
    glm::quat end = b;
    if (cosAngle < 0.0f) { // q and -q are the same rotation: take the nearer one
        cosAngle = -cosAngle;
        end = -b;
    }
    if (cosAngle > 0.9995f) { // nearly equal: sin(angle) underflows, and a lerp is exact enough
        return glm::normalize(a * (1.0f - t) + end * t);
    }
    const float angle = std::acos(cosAngle);
    const float sinAngle = std::sin(angle);
    return a * (std::sin((1.0f - t) * angle) / sinAngle) + end * (std::sin(t * angle) / sinAngle);
}

float sample(const Keyframes<float>& track, double time) {
    return sampleMixed(track, time);
}

glm::vec2 sample(const Keyframes<glm::vec2>& track, double time) {
    return sampleMixed(track, time);
}

glm::vec3 sample(const Keyframes<glm::vec3>& track, double time) {
    return sampleMixed(track, time);
}

glm::quat sample(const Keyframes<glm::quat>& track, double time) {
    const Segment s = findSegment(track.times, time);
    if (s.duration == 0.0 || track.interpolation == Interpolation::Step || s.u == 0.0f) {
        return glm::normalize(track.keyValue(s.key));
    }
    if (track.interpolation == Interpolation::CubicSpline) {
        return glm::normalize(hermite(track, s));
    }
    return slerpShortest(glm::normalize(track.keyValue(s.key)), glm::normalize(track.keyValue(s.key + 1)),
                         s.u);
}

} // namespace lumina::scene
