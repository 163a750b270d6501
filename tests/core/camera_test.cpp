// The rasteriser's projection and the path tracer's primary rays must agree pixel for pixel.
#include <gtest/gtest.h>

#include "gi/core/camera.h"

namespace lumina::gi {
namespace {

scene::Camera cornellCamera() {
    scene::Camera camera;
    camera.position = {278.0f, 273.0f, -800.0f};
    camera.forward = {0.0f, 0.0f, 1.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.fovY = 2.0f * std::atan(12.5f / 35.0f);
    camera.nearPlane = 1.0f;
    camera.farPlane = 3000.0f;
    return camera;
}

// Projects a world point with the GPU camera's rows, returning pixel coordinates.
glm::vec2 projectToPixel(const gpu::GpuCamera& camera, glm::vec3 world) {
    const glm::vec4 p(world, 1.0f);
    const glm::vec4 clip(glm::dot(camera.viewProjRows[0], p), glm::dot(camera.viewProjRows[1], p),
                         glm::dot(camera.viewProjRows[2], p), glm::dot(camera.viewProjRows[3], p));
    const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
    return {(ndc.x + 1.0f) * 0.5f * camera.imageSize.x, (1.0f - ndc.y) * 0.5f * camera.imageSize.y};
}

TEST(Camera, RayThroughPixelCentreProjectsBackToThatPixel) {
    const auto camera = makeGpuCamera(cornellCamera(), 64, 48);
    for (float y : {0.5f, 10.5f, 47.5f}) {
        for (float x : {0.5f, 31.5f, 63.5f}) {
            const glm::vec3 dir = gpu::cameraRayDirection(camera, {x, y});
            const glm::vec3 point = gpu::cameraPosition(camera) + dir * 700.0f;
            const glm::vec2 pixel = projectToPixel(camera, point);
            EXPECT_NEAR(pixel.x, x, 1e-3f);
            EXPECT_NEAR(pixel.y, y, 1e-3f);
        }
    }
}

TEST(Camera, RowZeroIsTheTopAndDepthRunsZeroToOne) {
    const auto camera = makeGpuCamera(cornellCamera(), 32, 32);
    EXPECT_GT(gpu::cameraRayDirection(camera, {16.0f, 0.5f}).y, 0.0f);
    EXPECT_LT(gpu::cameraRayDirection(camera, {16.0f, 31.5f}).y, 0.0f);
    // right = cross(forward, up) = -x here: the red wall (x = 552) is on the left, as published.
    EXPECT_LT(gpu::cameraRayDirection(camera, {31.5f, 16.0f}).x, 0.0f);

    auto depthAt = [&](float distance) {
        const glm::vec4 p(278.0f, 273.0f, -800.0f + distance, 1.0f);
        return glm::dot(camera.viewProjRows[2], p) / glm::dot(camera.viewProjRows[3], p);
    };
    EXPECT_NEAR(depthAt(1.0f), 0.0f, 1e-5f);
    EXPECT_NEAR(depthAt(3000.0f), 1.0f, 1e-5f);
}

TEST(Camera, VerticalFieldOfViewSpansTheImageHeight) {
    const auto camera = makeGpuCamera(cornellCamera(), 100, 100);
    const glm::vec3 top = gpu::cameraRayDirection(camera, {50.0f, 0.0f});
    const glm::vec3 bottom = gpu::cameraRayDirection(camera, {50.0f, 100.0f});
    EXPECT_NEAR(std::acos(glm::dot(top, bottom)), 2.0f * std::atan(12.5f / 35.0f), 1e-5f);
}

} // namespace
} // namespace lumina::gi
