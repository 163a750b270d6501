#pragma once
// The camera constants every renderer uploads, built from the scene's camera and the image
// size. The model itself (pixel centres, clip space, depth range) is written down once in
// shaders/common/camera_shared.h.
#include <cstdint>

#include <glm/glm.hpp>

#include "gi/scene/scene.h"
#include "shaders/common/camera_shared.h"

namespace lumina::gi {

// Right-handed view matrix and a perspective projection with depth 0 at the near plane and 1
// at the far plane, clip y up.
glm::mat4 viewMatrix(const scene::Camera& camera);
glm::mat4 projectionMatrix(const scene::Camera& camera, float aspect);

gpu::GpuCamera makeGpuCamera(const scene::Camera& camera, uint32_t width, uint32_t height);

} // namespace lumina::gi
