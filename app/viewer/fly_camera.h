#pragma once
// The fly camera: WASD/QE moves along the view, the mouse turns it (yaw about the world up the
// scene's camera starts with, pitch clamped short of the poles). Speed follows the scene's size:
// a quarter of its bounds' diagonal per second, times the wheel's multiplier.
#include "gi/scene/scene.h"

#include <string>

namespace lumina::app::viewer {

struct FlyInput {
    float forward = 0, right = 0, up = 0; // -1..1 each
    bool fast = false;
    float turnRight = 0, turnUp = 0; // radians this frame
    float wheel = 0;                 // notches this frame
};

class FlyCamera {
public:
    FlyCamera(const scene::Camera& start, const scene::Bounds& sceneBounds);

    // True when the camera moved.
    bool update(const FlyInput& input, float seconds);
    const scene::Camera& camera() const { return camera_; }
    // The camera with the world up it flies about as its up: the same view, and a FlyCamera
    // started from it flies as this one does (the saved settings' camera).
    scene::Camera uprightCamera() const {
        scene::Camera upright = camera_;
        upright.up = worldUp_;
        return upright;
    }
    float speed() const { return baseSpeed_ * speedScale_; }

private:
    scene::Camera camera_;
    glm::vec3 worldUp_;
    glm::vec3 referenceForward_; // yaw 0, horizontal
    float yaw_ = 0, pitch_ = 0;
    float baseSpeed_ = 1.0f;
    float speedScale_ = 1.0f;
};

// {"camera": {"position": ..., "forward": ..., "up": ..., "fovYDegrees": ..., "near": ..., "far": ...}},
// the scene-file form (docs/scenes.md), ready to paste into a scene .json.
std::string cameraJson(const scene::Camera& camera);

} // namespace lumina::app::viewer
