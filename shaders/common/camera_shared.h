#ifndef LUMINA_CAMERA_SHARED_H
#define LUMINA_CAMERA_SHARED_H
// The one camera model of Lumina, shared by the rasteriser and the path tracer so that their
// images compare pixel for pixel (docs/conventions.md):
//   - pixel (x, y) covers [x, x+1) x [y, y+1); its centre is (x + 0.5, y + 0.5); row 0 is the
//     top of the image;
//   - a pinhole camera with vertical field of view fovY; the image's right is
//     cross(forward, up), aspect = width / height;
//   - clip space: x right, y up, depth 0 at the near plane and 1 at the far plane (both APIs;
//     the Vulkan backend flips y with a negative-height viewport).
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct GpuCamera {
    float4 positionAndTanHalfFovY; // xyz: world position; w: tan(fovY / 2)
    float4 forwardAndAspect;       // xyz: unit forward; w: width / height
    float4 rightAndNear;           // xyz: unit right; w: near plane distance
    float4 upAndFar;               // xyz: unit up, orthogonal to forward; w: far plane distance
    float4 viewProjRows[4];        // clip = (dot(row0, p), dot(row1, p), dot(row2, p), dot(row3, p)), p = (world, 1)
    float4 imageSize;              // x: width; y: height; z: 1 / width; w: 1 / height
};

LUMINA_STATIC_ASSERT_SIZE(GpuCamera, 144);

// The unit world-space direction through image position `pixel` (pixel centres at +0.5).
LUMINA_INLINE float3 cameraRayDirection(GpuCamera camera, float2 pixel) {
    const float ndcX = 2.0f * pixel.x * camera.imageSize.z - 1.0f;
    const float ndcY = 1.0f - 2.0f * pixel.y * camera.imageSize.w;
    const float tanHalf = camera.positionAndTanHalfFovY.w;
    const float3 forward = float3(camera.forwardAndAspect.x, camera.forwardAndAspect.y, camera.forwardAndAspect.z);
    const float3 right = float3(camera.rightAndNear.x, camera.rightAndNear.y, camera.rightAndNear.z);
    const float3 up = float3(camera.upAndFar.x, camera.upAndFar.y, camera.upAndFar.z);
    const float3 direction = forward + right * (ndcX * tanHalf * camera.forwardAndAspect.w) + up * (ndcY * tanHalf);
    return direction * (1.0f / sqrt(dot(direction, direction)));
}

LUMINA_INLINE float3 cameraPosition(GpuCamera camera) {
    return float3(camera.positionAndTanHalfFovY.x, camera.positionAndTanHalfFovY.y, camera.positionAndTanHalfFovY.z);
}

LUMINA_GPU_NAMESPACE_END

#endif
