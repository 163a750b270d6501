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
    float3 position; // world
    float tanHalfFovY;
    float3 forward; // unit
    float aspect;   // width / height
    float3 right;   // unit
    float nearPlane;
    float3 up; // unit, orthogonal to forward
    float farPlane;
    float4 viewProjRows[4]; // clip = (dot(row0, p), dot(row1, p), dot(row2, p), dot(row3, p)), p = (world, 1)
    float2 imageSize;       // width, height in pixels
    float2 invImageSize;    // 1 / width, 1 / height
};

LUMINA_STATIC_ASSERT_SIZE(GpuCamera, 144);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, forward, 16);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, right, 32);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, up, 48);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, viewProjRows, 64);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, imageSize, 128);
LUMINA_STATIC_ASSERT_OFFSET(GpuCamera, invImageSize, 136);

// The unit world-space direction through image position `pixel` (pixel centres at +0.5).
LUMINA_INLINE float3 cameraRayDirection(GpuCamera camera, float2 pixel) {
    const float ndcX = 2.0f * pixel.x * camera.invImageSize.x - 1.0f;
    const float ndcY = 1.0f - 2.0f * pixel.y * camera.invImageSize.y;
    const float tanHalf = camera.tanHalfFovY;
    const float3 direction =
        camera.forward + camera.right * (ndcX * tanHalf * camera.aspect) + camera.up * (ndcY * tanHalf);
    return direction * (1.0f / sqrt(dot(direction, direction)));
}

LUMINA_INLINE float3 cameraPosition(GpuCamera camera) {
    return camera.position;
}

LUMINA_GPU_NAMESPACE_END

#endif
