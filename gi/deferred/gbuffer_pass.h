#pragma once
// GBuffer in two passes (docs/deferred.md, "GBuffer"): a visibility raster that keeps each
// pixel's triangle id and depth (shaders/deferred/gbuffer_visibility.hlsl), then a compute
// resolve that turns ids into albedo, world normal, material (emission + material index) and
// world position (+ view depth) (shaders/deferred/gbuffer_resolve.hlsl). Layouts in
// docs/deferred.md.
#include "gi/core/frame_context.h"
#include "gi/deferred/draw_lists.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"

#include <string_view>
#include <vector>

namespace lumina::gi {

struct GBuffer {
    rhi::TextureHandle albedo; // RGBA8_UNORM: linear albedo; a = 1 where a surface is
    rhi::TextureHandle normal; // RGBA16_FLOAT: unit world normal towards the viewer; a = 1 where a surface is
    rhi::TextureHandle material; // RGBA32_FLOAT: emitted radiance; a = material index
    rhi::TextureHandle position; // RGBA32_FLOAT: world position; w = view depth (0: no surface)
    rhi::TextureHandle depth;    // D32_FLOAT: 0 near, 1 far
    rhi::TextureHandle
        visibility; // R32_UINT: triangle id + front-face bit, 0: no surface (deferred_shared.h)

    static GBuffer create(rhi::IDevice& device, uint32_t width, uint32_t height);
};

class GBufferPass {
public:
    GBufferPass(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene);

    // Clears the visibility target and depth, draws every instance, resolves the attributes;
    // frameConstants holds DeferredFrameConstants. Timed as `passName` + " visibility" and
    // + " resolve" (another view of the scene, a probe's cube face, times apart).
    void record(FrameContext& frame, const GBuffer& gbuffer, const rhi::BufferHandle& frameConstants,
                std::string_view passName = "gbuffer") const;

private:
    const GpuScene& gpuScene_;
    // The GBuffer draw groups with GBufferVisibilityDrawConstants: one id range per draw.
    std::vector<GBufferDrawGroup> groups_;
    rhi::BufferHandle resolveDraws_; // GBufferResolveDraw per draw, sorted by firstId
    uint32_t drawCount_ = 0;
};

} // namespace lumina::gi
