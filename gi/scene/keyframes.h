#pragma once
// Keyframed values and their interpolation, as glTF 2.0 defines it (section 3.11, "Animations",
// and its Appendix C): STEP holds a key's value until the next key, LINEAR mixes neighbouring
// keys (rotations by spherical linear interpolation), CUBICSPLINE is the cubic Hermite spline
// through the keys with their in- and out-tangents. Before the first key a track holds the first
// value, after the last key the last value; looping is the caller's business (scene_animation.h).
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <vector>

namespace lumina::scene {

enum class Interpolation { Step, Linear, CubicSpline };

const char* interpolationName(Interpolation interpolation);

// A key is reached this many seconds early: key times and the time being sampled are both
// frame / framesPerSecond, but may be computed along different roundings; a step key written
// for frame N must hold at frame N. Far below any frame step (a millisecond at 1000 fps).
inline constexpr double kKeyTimeTolerance = 1e-7;

// One animated value over time. `times` are seconds, finite, not negative and strictly
// increasing (the loaders check). `values` holds one value per key, or with CubicSpline three
// per key in glTF's order: in-tangent, value, out-tangent (tangents are per second).
template <typename T>
struct Keyframes {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times;
    std::vector<T> values;

    bool empty() const { return times.empty(); }
    double endTime() const { return times.empty() ? 0.0 : times.back(); }
    // The value of key k (the middle of its triple for CubicSpline).
    const T& keyValue(size_t k) const {
        return interpolation == Interpolation::CubicSpline ? values[3 * k + 1] : values[k];
    }
};

// The track's value at `time` seconds; the track must not be empty.
float sample(const Keyframes<float>& track, double time);
glm::vec2 sample(const Keyframes<glm::vec2>& track, double time);
glm::vec3 sample(const Keyframes<glm::vec3>& track, double time);
// Unit length: linear keys are slerped along the shorter arc, cubic results normalised (glTF).
glm::quat sample(const Keyframes<glm::quat>& track, double time);

// Spherical linear interpolation from a to b (unit quaternions) along the shorter arc.
glm::quat slerpShortest(const glm::quat& a, const glm::quat& b, float t);

} // namespace lumina::scene
