#pragma once
// Point and spot light shadows (shaders/deferred/point_shadow.hlsl): one cube per
// shadow-casting light (at most LUMINA_MAX_SHADOWED_LIGHTS), six faces rendered as array
// layers 6 x cube + face of an R32F cube array holding distance / shadow range, with a D32
// array of the same layers for depth testing. A cube is re-rendered only when its light moved
// or changed range, or geometry moved within its range; the others keep their texels.
#include "gi/core/frame_context.h"
#include "gi/deferred/draw_lists.h"
#include "gi/gpu_scene/gpu_scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::gi {

class PointShadowPass {
public:
    static constexpr const char* kPassName = "point shadows";

    PointShadowPass(rhi::IDevice& device, const GpuScene& gpuScene, uint32_t faceSize);

    // cubes: per shadowed light, xyz position and w shadow range (DeferredShadowConstants::pointLights).
    // movedRegions: world boxes where geometry moved since the last call. Returns, per cube,
    // whether its content may have changed this frame (a forced re-render of an unchanged cube,
    // FrameContext::mayReuse, renders the same map and returns false).
    std::vector<bool> record(FrameContext& frame, const std::vector<glm::vec4>& cubes,
                             const rhi::BufferHandle& shadowConstants,
                             std::span<const scene::Bounds> movedRegions);

    // The cube array the direct-light pass samples (a cleared 1x1 cube while there is none).
    const rhi::TextureHandle& maps() const { return cubeCount_ > 0 ? distance_ : placeholder_; }
    uint32_t cubeCount() const { return cubeCount_; }
    uint32_t faceSize() const { return faceSize_; }

private:
    // True when the array was (re)allocated: every cube needs drawing.
    bool allocate(uint32_t cubes);
    void renderCube(FrameContext& frame, uint32_t cube, const rhi::BufferHandle& shadowConstants);

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
    std::vector<uint64_t> renderedFrames_; // per cube
};

} // namespace lumina::gi
