#include "gi/core/camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lumina::gi {

glm::mat4 viewMatrix(const scene::Camera& camera) {
    return glm::lookAtRH(camera.position, camera.position + camera.forward, camera.up);
}

glm::mat4 projectionMatrix(const scene::Camera& camera, float aspect) {
    // Depth 0..1 (D3D and Vulkan alike); GLM's default would be OpenGL's -1..1.
    return glm::perspectiveRH_ZO(camera.fovY, aspect, camera.nearPlane, camera.farPlane);
}

gpu::GpuCamera makeGpuCamera(const scene::Camera& camera, uint32_t width, uint32_t height) {
    const float aspect = float(width) / float(height);
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const glm::mat4 viewProj = projectionMatrix(camera, aspect) * viewMatrix(camera);

    gpu::GpuCamera out{};
    out.position = camera.position;
    out.tanHalfFovY = std::tan(camera.fovY * 0.5f);
    out.forward = forward;
    out.aspect = aspect;
    out.right = right;
    out.nearPlane = camera.nearPlane;
    out.up = up;
    out.farPlane = camera.farPlane;
    for (int r = 0; r < 4; ++r) {
        out.viewProjRows[r] = glm::vec4(viewProj[0][r], viewProj[1][r], viewProj[2][r], viewProj[3][r]);
    }
    out.imageSize = glm::vec2(float(width), float(height));
    out.invImageSize = glm::vec2(1.0f / float(width), 1.0f / float(height));
    return out;
}

} // namespace lumina::gi
