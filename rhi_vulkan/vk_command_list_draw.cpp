// Compute and graphics state, dispatches, draws, and the dynamic-rendering instances
// draws run in.
#include "rhi/error.h"
#include "rhi_vulkan/vk_binding.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_command_list.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_pipeline.h"
#include "rhi_vulkan/vk_struct.h"
#include "rhi_vulkan/vk_texture.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lumina::vulkan {

namespace {

using S = rhi::ResourceState;

bool sameLayout(const rhi::IBindingLayout& a, const rhi::IBindingLayout& b) {
    const rhi::BindingLayoutDesc& x = a.desc();
    const rhi::BindingLayoutDesc& y = b.desc();
    if (x.space != y.space || x.visibility != y.visibility || x.items.size() != y.items.size()) {
        return false;
    }
    for (size_t i = 0; i < x.items.size(); ++i) {
        if (x.items[i].type != y.items[i].type || x.items[i].reg != y.items[i].reg) {
            return false;
        }
    }
    return true;
}

} // namespace

std::vector<VkDescriptorSet> CommandList::writeBindings(const std::vector<rhi::BindingSet>& bindings,
                                                        const std::vector<rhi::BindingLayoutHandle>& layouts,
                                                        const std::string& pipelineName) {
    if (bindings.size() != layouts.size()) {
        throw rhi::Error("pipeline '" + pipelineName + "' has " + std::to_string(layouts.size()) +
                         " register spaces, but the state binds " + std::to_string(bindings.size()));
    }
    std::vector<VkDescriptorSet> sets;
    for (size_t space = 0; space < bindings.size(); ++space) {
        rhi::BindingSet set = bindings[space];
        if (!set.layout) {
            set.layout = layouts[space];
        } else if (set.layout != layouts[space] && !sameLayout(*set.layout, *layouts[space])) {
            throw rhi::Error("pipeline '" + pipelineName + "': the binding set for space" +
                             std::to_string(space) + " was made for another layout");
        }
        sets.push_back(writeBindingSet(*context_, descriptors_, set, "pipeline '" + pipelineName + "'"));
        for (const rhi::BindingSetItem& item : set.items) {
            keepAlive(item.buffer);
            keepAlive(item.texture);
            keepAlive(item.sampler);
        }
        keepAlive(set.layout);
    }
    return sets;
}

void CommandList::setComputeState(const rhi::ComputeState& state) {
    requireRecording("setComputeState");
    const auto* pipeline = dynamic_cast<const ComputePipeline*>(state.pipeline.get());
    if (!pipeline) {
        throw rhi::Error("setComputeState: no compute pipeline of this backend");
    }
    const std::vector<VkDescriptorSet> sets =
        writeBindings(state.bindings, pipeline->desc().layouts, pipeline->desc().debugName);
    vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->handle());
    if (!sets.empty()) {
        vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->layout().handle(),
                                0, static_cast<uint32_t>(sets.size()), sets.data(), 0, nullptr);
    }
    keepAlive(state.pipeline);
    computeState_ = state;
    pushConstantLayout_ = &pipeline->layout();
}

void CommandList::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
    requireRecording("dispatch");
    if (!computeState_) {
        throw rhi::Error("dispatch: no compute state set");
    }
    prepare([&] { requireBindings(computeState_->bindings); });
    vkCmdDispatch(commandBuffer_, groupsX, groupsY, groupsZ);
    finishCommand();
}

void CommandList::dispatchIndirect(rhi::IBuffer& args, uint64_t offset) {
    requireRecording("dispatchIndirect");
    if (!computeState_) {
        throw rhi::Error("dispatchIndirect: no compute state set");
    }
    Buffer& arguments = buffer(args, "dispatchIndirect");
    constexpr uint64_t kArgumentBytes = 3 * sizeof(uint32_t); // groups x, y, z
    if (!hasFlag(arguments.desc().usage, rhi::BufferUsage::Indirect) || offset % 4 != 0 ||
        offset + kArgumentBytes > arguments.desc().size) {
        throw rhi::Error("dispatchIndirect: buffer '" + arguments.debugName() +
                         "' needs BufferUsage::Indirect and 12 bytes at a 4-byte aligned offset " +
                         std::to_string(offset));
    }
    prepare([&] {
        requireBindings(computeState_->bindings);
        require(arguments, S::IndirectArgument);
    });
    vkCmdDispatchIndirect(commandBuffer_, arguments.handle(), offset);
    finishCommand();
}

void CommandList::setGraphicsState(const rhi::GraphicsState& state) {
    requireRecording("setGraphicsState");
    if (!hardware_->supportsGraphics) {
        throw rhi::Error(
            "setGraphicsState: this command list's queue family cannot draw (compute-only queue)");
    }
    const auto* pipeline = dynamic_cast<const GraphicsPipeline*>(state.pipeline.get());
    if (!pipeline) {
        throw rhi::Error("setGraphicsState: no graphics pipeline of this backend");
    }
    const rhi::GraphicsPipelineDesc& desc = pipeline->desc();
    const std::string where = "setGraphicsState (pipeline '" + desc.debugName + "'): ";
    if (state.colorAttachments.size() != desc.colorFormats.size()) {
        throw rhi::Error(where + std::to_string(state.colorAttachments.size()) + " colour attachments for " +
                         std::to_string(desc.colorFormats.size()) + " colour formats");
    }
    if (state.depthAttachment.has_value() != (desc.depthFormat != rhi::Format::Unknown)) {
        throw rhi::Error(where + "a depth attachment is needed exactly when the pipeline has a depth format");
    }
    std::optional<VkExtent3D> size;
    const auto checkAttachment = [&](const rhi::Attachment& attachment, rhi::Format format,
                                     rhi::TextureUsage usage, const std::string& role) {
        if (!attachment.texture) {
            throw rhi::Error(where + role + " has no texture");
        }
        Texture& target = texture(*attachment.texture, "setGraphicsState");
        if (target.desc().format != format || !hasFlag(target.desc().usage, usage)) {
            throw rhi::Error(where + role + " '" + target.debugName() + "' is " +
                             std::string(rhi::formatInfo(target.desc().format).name) +
                             ", the pipeline expects " + std::string(rhi::formatInfo(format).name) +
                             " with render-target or depth usage");
        }
        if (attachment.mipLevel >= target.desc().mipLevels || attachment.arrayLayer >= target.layerCount()) {
            throw rhi::Error(where + role + " '" + target.debugName() + "': mip or layer out of range");
        }
        if (!size) {
            size = target.mipExtent(attachment.mipLevel);
        }
    };
    for (size_t i = 0; i < state.colorAttachments.size(); ++i) {
        checkAttachment(state.colorAttachments[i], desc.colorFormats[i], rhi::TextureUsage::RenderTarget,
                        "colour attachment " + std::to_string(i));
    }
    if (state.depthAttachment) {
        checkAttachment(*state.depthAttachment, desc.depthFormat, rhi::TextureUsage::DepthStencil,
                        "depth attachment");
    }
    if (!size) {
        throw rhi::Error(where + "draws need at least one colour or depth attachment");
    }

    const std::vector<VkDescriptorSet> sets = writeBindings(state.bindings, desc.layouts, desc.debugName);
    vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->handle());
    if (!sets.empty()) {
        vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->layout().handle(),
                                0, static_cast<uint32_t>(sets.size()), sets.data(), 0, nullptr);
    }

    rhi::Viewport viewport = state.viewport;
    if (viewport.width == 0) {
        viewport.x = viewport.y = 0;
        viewport.width = static_cast<float>(size->width);
        viewport.height = static_cast<float>(size->height);
    }
    // Negative height: clip-space y points up as on D3D12, so vertex shaders stay identical
    // and images come out the same way up on both backends.
    const VkViewport vkViewport{viewport.x,        viewport.y + viewport.height,
                                viewport.width,    -viewport.height,
                                viewport.minDepth, viewport.maxDepth};
    vkCmdSetViewport(commandBuffer_, 0, 1, &vkViewport);
    rhi::Rect scissor;
    if (state.scissor) {
        scissor = *state.scissor;
    } else {
        scissor.x = static_cast<int32_t>(std::floor(viewport.x));
        scissor.y = static_cast<int32_t>(std::floor(viewport.y));
        scissor.width = static_cast<uint32_t>(std::ceil(viewport.width));
        scissor.height = static_cast<uint32_t>(std::ceil(viewport.height));
    }
    // Vulkan rejects negative scissor offsets; D3D12 clips them: clip here.
    const int32_t clipX = std::max(0, -scissor.x);
    const int32_t clipY = std::max(0, -scissor.y);
    const VkRect2D vkScissor{{scissor.x + clipX, scissor.y + clipY},
                             {scissor.width - std::min<uint32_t>(scissor.width, clipX),
                              scissor.height - std::min<uint32_t>(scissor.height, clipY)}};
    vkCmdSetScissor(commandBuffer_, 0, 1, &vkScissor);

    if (state.indexBuffer) {
        if (!state.indexBuffer->buffer) {
            throw rhi::Error(where + "index buffer binding without a buffer");
        }
        Buffer& indices = buffer(*state.indexBuffer->buffer, "setGraphicsState");
        if (!hasFlag(indices.desc().usage, rhi::BufferUsage::Index)) {
            throw rhi::Error(where + "buffer '" + indices.debugName() + "' lacks BufferUsage::Index");
        }
        vkCmdBindIndexBuffer(commandBuffer_, indices.handle(), state.indexBuffer->offset,
                             state.indexBuffer->format == rhi::IndexFormat::Uint16 ? VK_INDEX_TYPE_UINT16
                                                                                   : VK_INDEX_TYPE_UINT32);
    }
    keepAlive(state.pipeline);
    graphicsState_ = state;
    pushConstantLayout_ = &pipeline->layout();
}

CommandList::RenderingKey CommandList::renderingKeyOf(const rhi::GraphicsState& state) const {
    RenderingKey key;
    for (const rhi::Attachment& color : state.colorAttachments) {
        key.colors.push_back({color.texture.get(), color.mipLevel, color.arrayLayer});
    }
    if (state.depthAttachment) {
        const rhi::Attachment& depth = *state.depthAttachment;
        key.depth = AttachmentKey{depth.texture.get(), depth.mipLevel, depth.arrayLayer};
        key.depthReadOnly = !state.pipeline->desc().depth.writeEnable;
    }
    return key;
}

void CommandList::prepareDraw(const char* command, bool indexed) {
    requireRecording(command);
    if (!graphicsState_) {
        throw rhi::Error(std::string(command) + ": no graphics state set");
    }
    const rhi::GraphicsState& state = *graphicsState_;
    if (indexed && !state.indexBuffer) {
        throw rhi::Error(std::string(command) + ": the graphics state has no index buffer");
    }
    const RenderingKey key = renderingKeyOf(state);
    prepare(
        [&] {
            for (const rhi::Attachment& color : state.colorAttachments) {
                require(*color.texture, S::RenderTarget);
            }
            if (state.depthAttachment) {
                require(*state.depthAttachment->texture, key.depthReadOnly ? S::DepthRead : S::DepthWrite);
            }
            requireBindings(state.bindings);
            if (indexed) {
                require(*state.indexBuffer->buffer, S::IndexBuffer);
            }
        },
        /*staysInRendering=*/true);
    // Barriers ended the render pass; so do other attachments. Either way, begin again:
    // attachments always load, so splitting a pass loses nothing.
    if (!rendering_ || *rendering_ != key) {
        endRendering();
        beginRendering();
    }
}

void CommandList::beginRendering() {
    const rhi::GraphicsState& state = *graphicsState_;
    const RenderingKey key = renderingKeyOf(state);
    VkExtent2D area{~0u, ~0u};
    const auto attachmentInfo = [&](const rhi::Attachment& attachment, VkImageLayout layout, bool store) {
        auto& target = static_cast<Texture&>(*attachment.texture);
        const VkExtent3D extent = target.mipExtent(attachment.mipLevel);
        area.width = std::min(area.width, extent.width);
        area.height = std::min(area.height, extent.height);
        auto info = vkStruct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
        info.imageView = target.attachmentView(attachment.mipLevel, attachment.arrayLayer);
        info.imageLayout = layout;
        info.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        info.storeOp = store ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_NONE;
        return info;
    };
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const rhi::Attachment& color : state.colorAttachments) {
        colors.push_back(attachmentInfo(color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true));
    }
    auto depth = vkStruct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    if (state.depthAttachment) {
        // Read-only depth stores nothing: a store would count as a write to an image that
        // shaders may be sampling at the same time.
        depth = attachmentInfo(*state.depthAttachment,
                               key.depthReadOnly ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                                 : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                               !key.depthReadOnly);
    }
    auto info = vkStruct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    info.renderArea = {{0, 0}, area};
    info.layerCount = 1;
    info.colorAttachmentCount = static_cast<uint32_t>(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = state.depthAttachment ? &depth : nullptr;
    vkCmdBeginRendering(commandBuffer_, &info);
    rendering_ = key;
}

void CommandList::endRendering() {
    if (rendering_) {
        vkCmdEndRendering(commandBuffer_);
        rendering_.reset();
    }
}

void CommandList::draw(const rhi::DrawArgs& args) {
    prepareDraw("draw", false);
    vkCmdDraw(commandBuffer_, args.vertexOrIndexCount, args.instanceCount, args.firstVertexOrIndex,
              args.firstInstance);
    finishCommand();
}

void CommandList::drawIndexed(const rhi::DrawArgs& args) {
    prepareDraw("drawIndexed", true);
    vkCmdDrawIndexed(commandBuffer_, args.vertexOrIndexCount, args.instanceCount, args.firstVertexOrIndex,
                     args.vertexOffset, args.firstInstance);
    finishCommand();
}

} // namespace lumina::vulkan
