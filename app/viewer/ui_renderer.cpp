#include "app/viewer/ui_renderer.h"

#include "shaders/viewer/viewer_shared.h"

#include <algorithm>
#include <cstring>
#include <type_traits>

namespace lumina::app::viewer {

namespace {

static_assert(sizeof(ImDrawVert) == LUMINA_UI_VERTEX_BYTES, "ui.hlsl reads ImDrawVert as 20 bytes");
static_assert(sizeof(ImDrawIdx) == 2, "the index buffer is bound as 16-bit");

constexpr const char* kVertexKernel = "viewer/ui.vsMain";
constexpr const char* kPixelKernel = "viewer/ui.psMain";

gi::RasterPipelineState uiState() {
    gi::RasterPipelineState state;
    state.raster.cullMode = rhi::CullMode::None;
    state.depth.testEnable = false;
    state.depth.writeEnable = false;
    rhi::BlendState blend;
    blend.enable = true;
    blend.srcColor = rhi::BlendFactor::SrcAlpha;
    blend.dstColor = rhi::BlendFactor::OneMinusSrcAlpha;
    blend.srcAlpha = rhi::BlendFactor::One;
    blend.dstAlpha = rhi::BlendFactor::OneMinusSrcAlpha;
    state.blend = {blend};
    return state;
}

// Grows to the next power of two, so buffers are recreated a handful of times at most.
rhi::BufferHandle ensureCapacity(rhi::IDevice& device, rhi::BufferHandle buffer, uint64_t bytes,
                                 rhi::BufferUsage usage, const char* name) {
    if (buffer && buffer->desc().size >= bytes) {
        return buffer;
    }
    uint64_t size = 4096;
    while (size < bytes) {
        size *= 2;
    }
    return device.createBuffer({.size = size, .usage = usage, .debugName = name});
}

// ImTextureID is void* in Debian's Dear ImGui 1.86 and an integer in newer releases (vcpkg's).
ImTextureID toTextureId(size_t id) {
    if constexpr (std::is_pointer_v<ImTextureID>) {
        return reinterpret_cast<ImTextureID>(uintptr_t(id));
    } else {
        return ImTextureID(id);
    }
}

size_t fromTextureId(ImTextureID id) {
    if constexpr (std::is_pointer_v<ImTextureID>) {
        return size_t(reinterpret_cast<uintptr_t>(id));
    } else {
        return size_t(id);
    }
}

} // namespace

UiRenderer::UiRenderer(rhi::IDevice& device) : device_(device) {
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = "lumina-rhi";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    fontPixels_.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    font_ = device.createTexture({.format = rhi::Format::RGBA8_UNORM,
                                  .width = uint32_t(width),
                                  .height = uint32_t(height),
                                  .usage = rhi::TextureUsage::Sampled,
                                  .debugName = "viewer: ui font"});
    sampler_ = device.createSampler({.addressU = rhi::AddressMode::Clamp,
                                     .addressV = rhi::AddressMode::Clamp,
                                     .debugName = "viewer: ui sampler"});
    beginFrame();
}

void UiRenderer::beginFrame() {
    textures_.assign(1, font_);
    ImGui::GetIO().Fonts->SetTexID(toTextureId(1));
}

ImTextureID UiRenderer::texture(const rhi::TextureHandle& texture) {
    const auto it = std::find(textures_.begin(), textures_.end(), texture);
    if (it != textures_.end()) {
        return toTextureId(size_t(it - textures_.begin()) + 1);
    }
    textures_.push_back(texture);
    return toTextureId(textures_.size());
}

void UiRenderer::uploadGeometry(rhi::ICommandList& commands, const ImDrawData& data) {
    const uint64_t vertexBytes = uint64_t(data.TotalVtxCount) * sizeof(ImDrawVert);
    const uint64_t indexBytes = (uint64_t(data.TotalIdxCount) * sizeof(ImDrawIdx) + 3) & ~uint64_t(3);
    vertices_ = ensureCapacity(device_, vertices_, vertexBytes, rhi::BufferUsage::Raw, "viewer: ui vertices");
    indices_ = ensureCapacity(device_, indices_, indexBytes, rhi::BufferUsage::Index, "viewer: ui indices");
    std::vector<uint8_t> vertexData(vertexBytes), indexData(indexBytes, 0);
    size_t vertexAt = 0, indexAt = 0;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        std::memcpy(vertexData.data() + vertexAt, list.VtxBuffer.Data,
                    list.VtxBuffer.Size * sizeof(ImDrawVert));
        std::memcpy(indexData.data() + indexAt, list.IdxBuffer.Data, list.IdxBuffer.Size * sizeof(ImDrawIdx));
        vertexAt += list.VtxBuffer.Size * sizeof(ImDrawVert);
        indexAt += list.IdxBuffer.Size * sizeof(ImDrawIdx);
    }
    commands.writeBuffer(*vertices_, vertexData.data(), vertexBytes);
    commands.writeBuffer(*indices_, indexData.data(), indexBytes);
}

void UiRenderer::record(rhi::ICommandList& commands, gi::PipelineCache& pipelines, const ImDrawData& data,
                        const rhi::TextureHandle& target) {
    if (!fontUploaded_) {
        commands.writeTexture(*font_, {}, fontPixels_.data());
        fontUploaded_ = true;
    }
    if (data.TotalVtxCount == 0) {
        return;
    }
    uploadGeometry(commands, data);

    const float width = float(target->desc().width);
    const float height = float(target->desc().height);
    gpu::UiConstants constants{};
    // Pixel (DisplayPos .. DisplayPos + DisplaySize), y down, to clip space, y up.
    constants.scale = {2.0f / data.DisplaySize.x, -2.0f / data.DisplaySize.y};
    constants.translate = {-1.0f - data.DisplayPos.x * 2.0f / data.DisplaySize.x,
                           1.0f + data.DisplayPos.y * 2.0f / data.DisplaySize.y};

    commands.beginTimer("viewer: ui");
    uint32_t vertexBase = 0, indexBase = 0;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback != nullptr) {
                continue; // the viewer installs none
            }
            // Clip rectangles are in display units; the target is in framebuffer pixels.
            const ImVec2 scale = data.FramebufferScale;
            const float x0 = std::max((cmd.ClipRect.x - data.DisplayPos.x) * scale.x, 0.0f);
            const float y0 = std::max((cmd.ClipRect.y - data.DisplayPos.y) * scale.y, 0.0f);
            const float x1 = std::min((cmd.ClipRect.z - data.DisplayPos.x) * scale.x, width);
            const float y1 = std::min((cmd.ClipRect.w - data.DisplayPos.y) * scale.y, height);
            if (x1 <= x0 || y1 <= y0 || cmd.ElemCount == 0) {
                continue;
            }
            const size_t id = fromTextureId(cmd.GetTexID());
            const rhi::TextureHandle& texture = textures_.at(id - 1);
            gi::SpaceBindings bindings(1);
            bindings[0] = {rhi::BindingSetItem::rawBuffer(0, vertices_),
                           rhi::BindingSetItem::sampledTexture(1, texture),
                           rhi::BindingSetItem::samplerState(0, sampler_)};
            const auto& entry =
                pipelines.graphics(kVertexKernel, kPixelKernel, bindings, sizeof(gpu::UiConstants), uiState(),
                                   {target->desc().format}, rhi::Format::Unknown);
            rhi::GraphicsState state;
            state.pipeline = entry.pipeline;
            state.colorAttachments = {{target}};
            state.bindings = {rhi::BindingSet{entry.layouts[0], bindings[0]}};
            state.scissor =
                rhi::Rect{int32_t(x0), int32_t(y0), uint32_t(x1 - int32_t(x0)), uint32_t(y1 - int32_t(y0))};
            state.indexBuffer = rhi::IndexBufferBinding{indices_, rhi::IndexFormat::Uint16, 0};
            commands.setGraphicsState(state);
            constants.vertexBase = vertexBase + cmd.VtxOffset;
            commands.pushConstants(constants);
            commands.drawIndexed(
                {.vertexOrIndexCount = cmd.ElemCount, .firstVertexOrIndex = indexBase + cmd.IdxOffset});
        }
        vertexBase += uint32_t(list.VtxBuffer.Size);
        indexBase += uint32_t(list.IdxBuffer.Size);
    }
    commands.endTimer();
}

} // namespace lumina::app::viewer
