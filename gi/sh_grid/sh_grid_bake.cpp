#include "gi/sh_grid/sh_grid_bake.h"

#include "gi/core/camera.h"
#include "gi/core/gpu_resources.h"
#include "shaders/deferred/deferred_shared.h"

#include <algorithm>
#include <string>

namespace lumina::gi {

scene::Camera shGridFaceCamera(const glm::vec3& position, uint32_t face, float nearPlane, float farPlane) {
    static constexpr glm::vec3 kForward[LUMINA_SH_GRID_FACES] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    // Any up orthogonal to the axis: the projection reads right and up back from the camera.
    static constexpr glm::vec3 kUp[LUMINA_SH_GRID_FACES] = {{0, 1, 0},  {0, 1, 0}, {0, 0, 1},
                                                            {0, 0, -1}, {0, 1, 0}, {0, 1, 0}};
    scene::Camera camera;
    camera.name = "sh grid face " + std::to_string(face);
    camera.position = position;
    camera.forward = kForward[face];
    camera.up = kUp[face];
    camera.fovY = 0.5f * LUMINA_PI;
    camera.nearPlane = nearPlane;
    camera.farPlane = farPlane;
    return camera;
}

gpu::ShGridFaceConstants shGridFaceConstants(const gpu::GpuCamera& camera, uint32_t face, uint32_t faceSize,
                                             bool bounce) {
    gpu::ShGridFaceConstants c{};
    c.forward = gpu::float4(camera.forward, 0.0f);
    c.right = gpu::float4(camera.right, 0.0f);
    c.up = gpu::float4(camera.up, 0.0f);
    c.face = face;
    c.faceSize = faceSize;
    c.bounce = bounce ? 1u : 0u;
    return c;
}

ShGridBake::ShGridBake(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                       const ShGridSettings& settings)
    : faceSize_(settings.faceSize), bounce_(settings.bounce), sky_(gpuScene.sky),
      gbufferPass_(device, scene, gpuScene),
      face_(GBuffer::create(device, settings.faceSize, settings.faceSize)),
      radiance_(createStorageTexture2d(device, rhi::Format::RGBA16_FLOAT, settings.faceSize,
                                       settings.faceSize, "sh grid: face radiance")) {
    const scene::Bounds box = scene.worldBounds();
    const float diagonal = glm::length(box.max - box.min);
    // Near enough to see a wall a fraction of a cell away; far enough for the whole scene.
    nearPlane_ = 1e-4f * diagonal;
    farPlane_ = 2.0f * diagonal;
    for (uint32_t i = 0; i < settings.probesPerFrame * LUMINA_SH_GRID_FACES; ++i) {
        faceCameras_.push_back(device.createBuffer({.size = sizeof(gpu::DeferredFrameConstants),
                                                    .usage = rhi::BufferUsage::Constant,
                                                    .debugName = "sh grid: face camera"}));
    }
}

void ShGridBake::record(FrameContext& frame, const DeferredRenderer& deferred, const ShGridResources& r,
                        std::span<const uint32_t> probes) {
    const ShadowedLights lights = deferred.shadowedLights();
    const size_t count = std::min(probes.size(), faceCameras_.size() / LUMINA_SH_GRID_FACES);
    std::vector<gpu::ShGridFaceConstants> projections;
    // Every face's camera first: each buffer is written once per frame, before any pass reads it.
    for (size_t slot = 0; slot < count; ++slot) {
        const glm::vec3 position = r.layout.position(probes[slot]);
        for (uint32_t face = 0; face < LUMINA_SH_GRID_FACES; ++face) {
            gpu::DeferredFrameConstants constants{};
            constants.camera =
                makeGpuCamera(shGridFaceCamera(position, face, nearPlane_, farPlane_), faceSize_, faceSize_);
            constants.lightCount = lights.lightCount;
            constants.width = faceSize_;
            constants.height = faceSize_;
            frame.commands().writeBuffer(*faceCameras_[slot * LUMINA_SH_GRID_FACES + face], &constants,
                                         sizeof(constants));
            projections.push_back(shGridFaceConstants(constants.camera, face, faceSize_, bounce_));
        }
    }
    for (size_t slot = 0; slot < count; ++slot) {
        for (uint32_t face = 0; face < LUMINA_SH_GRID_FACES; ++face) {
            const size_t index = slot * LUMINA_SH_GRID_FACES + face;
            gbufferPass_.record(frame, face_, faceCameras_[index], kGBufferName);
            directLight_.record(frame,
                                {.gbuffer = face_,
                                 .frameConstants = faceCameras_[index],
                                 .shadowConstants = lights.shadowConstants,
                                 .lights = lights.lights,
                                 .sunShadowMap = lights.sunShadowMap,
                                 .pointShadowMaps = lights.pointShadowMaps,
                                 .sky = sky_},
                                radiance_, kDirectName);
            project_.record(frame, r, radiance_, face_, projections[index]);
        }
        combine_.record(frame, r, probes[slot]);
    }
}

} // namespace lumina::gi
