// Compute and graphics state, dispatches and draws of d3d12::CommandList.
#include "rhi_d3d12/d3d12_buffer.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_command_list.h"
#include "rhi_d3d12/d3d12_format.h"
#include "rhi_d3d12/d3d12_pipeline.h"
#include "rhi_d3d12/d3d12_texture.h"

namespace lumina::d3d12 {

namespace {
constexpr uint64_t kDispatchArgsBytes = sizeof(D3D12_DISPATCH_ARGUMENTS);
}

void CommandList::bindTables(const std::vector<rhi::BindingLayoutHandle>& layouts,
                             const std::vector<rhi::BindingSet>& sets, const RootSignature& root,
                             bool compute, const std::string& pipelineName) {
    if (sets.size() != layouts.size()) {
        throw rhi::Error("pipeline '" + pipelineName + "' has " + std::to_string(layouts.size()) +
                         " binding layouts, the state binds " + std::to_string(sets.size()) + " sets");
    }
    stateUses_.clear();
    for (size_t i = 0; i < sets.size(); ++i) {
        const BindingLayout& layout = toBindingLayout(*layouts[i]);
        WrittenBindingSet tables =
            writeBindingSet(context_->device(), layout, sets[i], viewTables_, samplerTables_);
        const RootSignature::Tables& parameters = root.tables[i];
        if (parameters.resources >= 0) {
            compute ? list_->SetComputeRootDescriptorTable(UINT(parameters.resources), tables.resources)
                    : list_->SetGraphicsRootDescriptorTable(UINT(parameters.resources), tables.resources);
        }
        if (parameters.samplers >= 0) {
            compute ? list_->SetComputeRootDescriptorTable(UINT(parameters.samplers), tables.samplers)
                    : list_->SetGraphicsRootDescriptorTable(UINT(parameters.samplers), tables.samplers);
        }
        for (const WrittenBindingSet::Use& bound : tables.uses) {
            keepAlive(nativeResource(*bound.resource));
            stateUses_.push_back(bound);
        }
    }
}

void CommandList::setComputeState(const rhi::ComputeState& state) {
    requireOpen("setComputeState()");
    requireQueue("setComputeState()", false);
    const auto* pipeline = dynamic_cast<const ComputePipeline*>(state.pipeline.get());
    if (!pipeline) {
        throw rhi::Error("setComputeState on '" + name_ + "': the pipeline is null or from another backend");
    }
    list_->SetComputeRootSignature(pipeline->root().native.Get());
    list_->SetPipelineState(pipeline->pso());
    bindTables(pipeline->desc().layouts, state.bindings, pipeline->root(), true, pipeline->desc().debugName);
    keptObjects_.push_back(state.pipeline);
    computePipeline_ = state.pipeline;
    graphicsPipeline_.reset();
    indexBuffer_.reset();
    root_ = &pipeline->root();
    rootIsCompute_ = true;
}

void CommandList::setPushConstants(const void* data, uint32_t size) {
    requireOpen("setPushConstants()");
    if (!root_) {
        throw rhi::Error("setPushConstants on '" + name_ + "' before setComputeState or setGraphicsState");
    }
    if (size % 4 != 0 || size > root_->pushConstantBytes) {
        throw rhi::Error("setPushConstants on '" + name_ + "': " + std::to_string(size) +
                         " bytes, the pipeline declares " + std::to_string(root_->pushConstantBytes) +
                         " (a multiple of 4)");
    }
    if (size == 0) {
        return;
    }
    if (rootIsCompute_) {
        list_->SetComputeRoot32BitConstants(RootSignature::kPushConstantParameter, size / 4, data, 0);
    } else {
        list_->SetGraphicsRoot32BitConstants(RootSignature::kPushConstantParameter, size / 4, data, 0);
    }
}

void CommandList::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
    requireOpen("dispatch()");
    if (!computePipeline_) {
        throw rhi::Error("dispatch on '" + name_ + "' without setComputeState");
    }
    for (const WrittenBindingSet::Use& u : stateUses_) {
        use(*u.resource, u.state);
    }
    flushBarriers();
    list_->Dispatch(groupsX, groupsY, groupsZ);
    commandRecorded();
}

void CommandList::dispatchIndirect(rhi::IBuffer& args, uint64_t offset) {
    requireOpen("dispatchIndirect()");
    if (!computePipeline_) {
        throw rhi::Error("dispatchIndirect on '" + name_ + "' without setComputeState");
    }
    if (!rhi::hasFlag(args.desc().usage, rhi::BufferUsage::Indirect)) {
        throw rhi::Error("dispatchIndirect: buffer '" + args.debugName() + "' lacks BufferUsage::Indirect");
    }
    if (offset % 4 != 0 || offset + kDispatchArgsBytes > args.desc().size) {
        throw rhi::Error("dispatchIndirect: offset " + std::to_string(offset) + " of buffer '" +
                         args.debugName() + "' is not 4-byte aligned or leaves less than 12 bytes");
    }
    for (const WrittenBindingSet::Use& u : stateUses_) {
        use(*u.resource, u.state);
    }
    use(args, rhi::ResourceState::IndirectArgument);
    flushBarriers();
    list_->ExecuteIndirect(shared_->dispatchSignature.Get(), 1, toBuffer(args).native(), offset, nullptr, 0);
    commandRecorded();
}

void CommandList::setGraphicsState(const rhi::GraphicsState& state) {
    requireOpen("setGraphicsState()");
    requireQueue("setGraphicsState()", true);
    const auto* pipeline = dynamic_cast<const GraphicsPipeline*>(state.pipeline.get());
    if (!pipeline) {
        throw rhi::Error("setGraphicsState on '" + name_ + "': the pipeline is null or from another backend");
    }
    const rhi::GraphicsPipelineDesc& desc = pipeline->desc();
    const std::string what = "setGraphicsState('" + desc.debugName + "')";
    if (state.colorAttachments.size() != desc.colorFormats.size()) {
        throw rhi::Error(what + ": " + std::to_string(state.colorAttachments.size()) +
                         " colour attachments for a pipeline with " +
                         std::to_string(desc.colorFormats.size()));
    }
    if (state.depthAttachment.has_value() != (desc.depthFormat != rhi::Format::Unknown)) {
        throw rhi::Error(what +
                         ": a depth attachment must be given exactly when the pipeline has a depth format");
    }
    list_->SetGraphicsRootSignature(pipeline->root().native.Get());
    list_->SetPipelineState(pipeline->pso());
    bindTables(desc.layouts, state.bindings, pipeline->root(), false, desc.debugName);

    std::vector<D3D12_CPU_DESCRIPTOR_HANDLE> targets;
    uint32_t width = 0;
    uint32_t height = 0;
    for (size_t i = 0; i < state.colorAttachments.size(); ++i) {
        const rhi::Attachment& attachment = state.colorAttachments[i];
        if (!attachment.texture) {
            throw rhi::Error(what + ": colour attachment " + std::to_string(i) + " has no texture");
        }
        Texture& texture = toTexture(*attachment.texture);
        if (texture.desc().format != desc.colorFormats[i]) {
            throw rhi::Error(what + ": colour attachment " + std::to_string(i) + " ('" +
                             texture.desc().debugName + "') has another format than the pipeline's");
        }
        targets.push_back(texture.rtv(attachment.mipLevel, attachment.arrayLayer));
        keepAlive(texture);
        stateUses_.push_back({attachment.texture.get(), rhi::ResourceState::RenderTarget});
        if (i == 0) {
            width = rhi::mipExtent(texture.desc().width, attachment.mipLevel);
            height = rhi::mipExtent(texture.desc().height, attachment.mipLevel);
        }
    }
    D3D12_CPU_DESCRIPTOR_HANDLE depthView{};
    if (state.depthAttachment) {
        const rhi::Attachment& attachment = *state.depthAttachment;
        if (!attachment.texture) {
            throw rhi::Error(what + ": the depth attachment has no texture");
        }
        Texture& texture = toTexture(*attachment.texture);
        const bool writes = desc.depth.testEnable && desc.depth.writeEnable;
        depthView = texture.dsv(attachment.mipLevel, attachment.arrayLayer, false, !writes);
        keepAlive(texture);
        stateUses_.push_back({attachment.texture.get(),
                              writes ? rhi::ResourceState::DepthWrite : rhi::ResourceState::DepthRead});
        if (targets.empty()) {
            width = rhi::mipExtent(texture.desc().width, attachment.mipLevel);
            height = rhi::mipExtent(texture.desc().height, attachment.mipLevel);
        }
    }
    list_->OMSetRenderTargets(static_cast<UINT>(targets.size()), targets.empty() ? nullptr : targets.data(),
                              FALSE, state.depthAttachment ? &depthView : nullptr);

    rhi::Viewport viewport = state.viewport;
    if (viewport.width == 0) {
        viewport = {0, 0, float(width), float(height), viewport.minDepth, viewport.maxDepth};
    }
    const D3D12_VIEWPORT nativeViewport{viewport.x,      viewport.y,        viewport.width,
                                        viewport.height, viewport.minDepth, viewport.maxDepth};
    list_->RSSetViewports(1, &nativeViewport);
    const rhi::Rect scissor = state.scissor.value_or(rhi::Rect{
        int32_t(viewport.x), int32_t(viewport.y), uint32_t(viewport.width), uint32_t(viewport.height)});
    const D3D12_RECT nativeScissor{scissor.x, scissor.y, LONG(scissor.x + int32_t(scissor.width)),
                                   LONG(scissor.y + int32_t(scissor.height))};
    list_->RSSetScissorRects(1, &nativeScissor);
    list_->IASetPrimitiveTopology(pipeline->topology());

    indexBuffer_ = state.indexBuffer;
    if (indexBuffer_) {
        if (!indexBuffer_->buffer) {
            throw rhi::Error(what + ": the index buffer binding has no buffer");
        }
        Buffer& buffer = toBuffer(*indexBuffer_->buffer);
        if (!rhi::hasFlag(buffer.desc().usage, rhi::BufferUsage::Index)) {
            throw rhi::Error(what + ": buffer '" + buffer.desc().debugName + "' lacks BufferUsage::Index");
        }
        if (indexBuffer_->offset >= buffer.desc().size) {
            throw rhi::Error(what + ": index buffer offset is past the end of '" + buffer.desc().debugName +
                             "'");
        }
        D3D12_INDEX_BUFFER_VIEW view{};
        view.BufferLocation = buffer.gpuAddress() + indexBuffer_->offset;
        view.SizeInBytes = static_cast<UINT>(buffer.desc().size - indexBuffer_->offset);
        view.Format =
            indexBuffer_->format == rhi::IndexFormat::Uint16 ? DXGI_FORMAT_R16_UINT : DXGI_FORMAT_R32_UINT;
        list_->IASetIndexBuffer(&view);
        keepAlive(buffer);
        stateUses_.push_back({indexBuffer_->buffer.get(), rhi::ResourceState::IndexBuffer});
    }
    keptObjects_.push_back(state.pipeline);
    graphicsPipeline_ = state.pipeline;
    computePipeline_.reset();
    root_ = &pipeline->root();
    rootIsCompute_ = false;
}

void CommandList::prepareDraw(const char* command) {
    requireOpen(command);
    if (!graphicsPipeline_) {
        throw rhi::Error(std::string(command) + " on '" + name_ + "' without setGraphicsState");
    }
    for (const WrittenBindingSet::Use& u : stateUses_) {
        use(*u.resource, u.state);
    }
    flushBarriers();
}

void CommandList::draw(const rhi::DrawArgs& args) {
    prepareDraw("draw()");
    list_->DrawInstanced(args.vertexOrIndexCount, args.instanceCount, args.firstVertexOrIndex,
                         args.firstInstance);
    commandRecorded();
}

void CommandList::drawIndexed(const rhi::DrawArgs& args) {
    if (!indexBuffer_) {
        throw rhi::Error("drawIndexed on '" + name_ + "' without an index buffer in the graphics state");
    }
    prepareDraw("drawIndexed()");
    list_->DrawIndexedInstanced(args.vertexOrIndexCount, args.instanceCount, args.firstVertexOrIndex,
                                args.vertexOffset, args.firstInstance);
    commandRecorded();
}

} // namespace lumina::d3d12
