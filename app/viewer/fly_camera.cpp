#include "app/viewer/fly_camera.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace lumina::app::viewer {

namespace {

// The pitch stops this far short of straight up or down, where yaw would be undefined.
constexpr float kMaxPitch = 0.49f * std::numbers::pi_v<float>;
constexpr float kSpeedPerDiagonal = 0.25f; // bounds diagonals per second
constexpr float kFastFactor = 4.0f;
constexpr float kWheelStep = 1.25f; // speed factor per wheel notch

} // namespace

FlyCamera::FlyCamera(const scene::Camera& start, const scene::Bounds& bounds) : camera_(start) {
    worldUp_ = glm::normalize(start.up);
    // Yaw and pitch in a frame whose y is the world up and whose -z is the start's forward
    // projected onto the horizontal plane.
    const glm::vec3 forward = glm::normalize(start.forward);
    pitch_ = std::asin(std::clamp(glm::dot(forward, worldUp_), -1.0f, 1.0f));
    yaw_ = 0.0f;
    const glm::vec3 horizontal = forward - worldUp_ * glm::dot(forward, worldUp_);
    referenceForward_ = glm::length(horizontal) > 1e-6f
                            ? glm::normalize(horizontal)
                            : glm::normalize(glm::cross(worldUp_, glm::vec3(1, 0, 0)));
    const float diagonal = glm::length(bounds.max - bounds.min);
    baseSpeed_ = std::isfinite(diagonal) && diagonal > 0.0f ? kSpeedPerDiagonal * diagonal : 1.0f;
}

bool FlyCamera::update(const FlyInput& input, float seconds) {
    if (input.wheel != 0.0f) {
        speedScale_ = std::clamp(speedScale_ * std::pow(kWheelStep, input.wheel), 1e-3f, 1e3f);
    }
    const bool turned = input.turnRight != 0.0f || input.turnUp != 0.0f;
    const bool moved = input.forward != 0.0f || input.right != 0.0f || input.up != 0.0f;
    if (!turned && !moved) {
        return false;
    }
    yaw_ -= input.turnRight;
    pitch_ = std::clamp(pitch_ + input.turnUp, -kMaxPitch, kMaxPitch);
    const glm::vec3 side = glm::normalize(glm::cross(referenceForward_, worldUp_));
    const glm::vec3 horizontal = std::cos(yaw_) * referenceForward_ - std::sin(yaw_) * side;
    camera_.forward = glm::normalize(std::cos(pitch_) * horizontal + std::sin(pitch_) * worldUp_);
    const glm::vec3 right = glm::normalize(glm::cross(camera_.forward, worldUp_));
    camera_.up = glm::normalize(glm::cross(right, camera_.forward));

    const float step = speed() * (input.fast ? kFastFactor : 1.0f) * seconds;
    camera_.position += step * (input.forward * camera_.forward + input.right * right + input.up * worldUp_);
    return true;
}

std::string cameraJson(const scene::Camera& camera) {
    std::ostringstream out;
    out << std::setprecision(7);
    const auto vec = [&](const glm::vec3& v) { out << '[' << v.x << ", " << v.y << ", " << v.z << ']'; };
    out << "\"camera\": {\"position\": ";
    vec(camera.position);
    out << ", \"forward\": ";
    vec(camera.forward);
    out << ", \"up\": ";
    vec(camera.up);
    out << ", \"fovYDegrees\": " << camera.fovY * 180.0f / std::numbers::pi_v<float> << ", \"near\": "
        << camera.nearPlane << ", \"far\": " << camera.farPlane << '}';
    return out.str();
}

} // namespace lumina::app::viewer
