#pragma once
// GBuffer by raster (shaders/deferred/gbuffer.hlsl): albedo, world normal, material
// (emission + material index), world position (+ view depth) and depth. Layouts in
// docs/deferred.md.
#include "gi/core/frame_context.h"
#include "gi/deferred/draw_lists.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"

#include <vector>

namespace lumina::gi {

struct GBuffer {
    rhi::TextureHandle albedo; // RGBA8_UNORM: linear albedo; a = 1 where a surface is
    rhi::TextureHandle normal; // RGBA16_FLOAT: unit world normal towards the viewer; a = 1 where a surface is
    rhi::TextureHandle material; // RGBA32_FLOAT: emitted radiance; a = material index
    rhi::TextureHandle position; // RGBA32_FLOAT: world position; w = view depth (0: no surface)
    rhi::TextureHandle depth;    // D32_FLOAT: 0 near, 1 far

    static GBuffer create(rhi::IDevice& device, uint32_t width, uint32_t height);
};

class GBufferPass {
public:
    GBufferPass(const scene::Scene& scene, const GpuScene& gpuScene);

    // Clears the targets and draws every instance; frameConstants holds DeferredFrameConstants.
    // Timed as `passName` (another view of the scene, a probe's cube face, times apart).
    void record(FrameContext& frame, const GBuffer& gbuffer, const rhi::BufferHandle& frameConstants,
                std::string_view passName = "gbuffer") const;

private:
    const GpuScene& gpuScene_;
    std::vector<GBufferDrawGroup> groups_;
};

} // namespace lumina::gi
