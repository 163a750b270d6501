#pragma once
// Dear ImGui's draw data through the RHI, with the viewer's one graphics pipeline
// (shaders/viewer/ui.hlsl), so both APIs draw the UI alike and no ImGui rendering backend is
// used. Textures are named to ImGui by small integer ids handed out per frame; id 1 is the
// font atlas.
#include "gi/core/pipeline_cache.h"
#include "rhi/rhi.h"

#include <imgui.h>
#include <vector>

namespace lumina::app::viewer {

class UiRenderer {
public:
    // Builds the font atlas of the current ImGui context.
    explicit UiRenderer(rhi::IDevice& device);

    // Forgets the textures of the last frame (not the font).
    void beginFrame();
    // An id for ImGui::Image and draw lists, valid until the next beginFrame().
    ImTextureID texture(const rhi::TextureHandle& texture);
    // Draws `data` into `target` (RGBA8_UNORM, loaded, not cleared).
    // `pipelines` may be a new cache each time (shader hot reload).
    void record(rhi::ICommandList& commands, gi::PipelineCache& pipelines, const ImDrawData& data,
                const rhi::TextureHandle& target);

private:
    void uploadGeometry(rhi::ICommandList& commands, const ImDrawData& data);

    rhi::IDevice& device_;
    rhi::TextureHandle font_;
    bool fontUploaded_ = false;
    std::vector<unsigned char> fontPixels_;
    rhi::SamplerHandle sampler_;
    std::vector<rhi::TextureHandle> textures_; // id - 1
    rhi::BufferHandle vertices_;
    rhi::BufferHandle indices_;
};

} // namespace lumina::app::viewer
