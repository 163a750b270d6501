#pragma once
// Point and spot light shadows (shaders/deferred/point_shadow.hlsl): one cube per
// shadow-casting light (at most LUMINA_MAX_SHADOWED_LIGHTS), six faces rendered as array
// layers 6 x cube + face of an R32F cube array holding distance / shadow range, with a D32
// array of the same layers for depth testing. Re-rendered only when a shadowed light or the
// geometry changes.
#include "gi/core/frame_context.h"
#include "gi/deferred/draw_lists.h"
#include "gi/gpu_scene/gpu_scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lumina::gi {

class PointShadowPass {
public:
    PointShadowPass(rhi::IDevice& device, const GpuScene& gpuScene, uint32_t faceSize);

    // cubes: per shadowed light, xyz position and w shadow range (DeferredShadowConstants::pointLights).
    void record(FrameContext& frame, const std::vector<glm::vec4>& cubes,
                const rhi::BufferHandle& shadowConstants, uint64_t geometryVersion);

    // The cube array the direct-light pass samples (a cleared 1x1 cube while there is none).
    const rhi::TextureHandle& maps() const { return cubeCount_ > 0 ? distance_ : placeholder_; }
    uint32_t cubeCount() const { return cubeCount_; }
    uint32_t faceSize() const { return faceSize_; }

private:
    void allocate(uint32_t cubes);

    rhi::IDevice& device_;
    const GpuScene& gpuScene_;
    uint32_t faceSize_;
    std::vector<ShadowDraw> draws_;
    rhi::TextureHandle distance_; // R32F cube array
    rhi::TextureHandle depth_;    // D32 2D array, same layers
    uint32_t allocatedCubes_ = 0;
    uint32_t cubeCount_ = 0;
    rhi::TextureHandle placeholder_;
    bool placeholderCleared_ = false;
    std::vector<glm::vec4> renderedCubes_;
    uint64_t renderedGeometry_ = 0;
    uint64_t renderedFrame_ = 0;
};

} // namespace lumina::gi
