#pragma once
// The sun's shadow map (shaders/deferred/sun_shadow.hlsl): depth only, orthographic, fitted
// to the whole scene so that the camera can move without invalidating it. Re-rendered only
// when the sun's projection or the geometry changes; otherwise the pass records why it
// skipped.
#include "gi/core/frame_context.h"
#include "gi/deferred/draw_lists.h"
#include "gi/deferred/light_setup.h"
#include "gi/gpu_scene/gpu_scene.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace lumina::gi {

class SunShadowPass {
public:
    static constexpr const char* kPassName = "sun shadow";

    SunShadowPass(rhi::IDevice& device, const GpuScene& gpuScene, uint32_t mapSize);

    // `fit` is empty when the scene has no directional light. shadowConstants holds
    // DeferredShadowConstants (with `fit` in it); geometryMoved: an instance moved since the last
    // call (the map covers the whole scene, so any move re-renders it). True when it rendered a
    // map that may differ from the last (a forced re-render of an unchanged map returns false).
    bool record(FrameContext& frame, const std::optional<SunShadowFit>& fit,
                const rhi::BufferHandle& shadowConstants, bool geometryMoved);

    // The map the direct-light pass samples: a cleared 1x1 map while there is no sun.
    const rhi::TextureHandle& map() const { return valid_ ? map_ : placeholder_; }
    bool valid() const { return valid_; }
    uint32_t mapSize() const { return mapSize_; }

private:
    rhi::IDevice& device_;
    const GpuScene& gpuScene_;
    uint32_t mapSize_;
    std::vector<ShadowDraw> draws_;
    rhi::TextureHandle map_;
    rhi::TextureHandle placeholder_;
    bool placeholderCleared_ = false;
    bool valid_ = false;
    std::array<glm::vec4, 4> renderedRows_{};
    uint64_t renderedFrame_ = 0;
};

} // namespace lumina::gi
