#include "gi/core/frame_context.h"

#include "gi/core/finite_check.h"

namespace lumina::gi {

template <typename Self>
std::vector<rhi::BindingSet>
PassBindings<Self>::bindingSets(const std::vector<rhi::BindingLayoutHandle>& layouts) const {
    std::vector<rhi::BindingSet> sets;
    for (size_t space = 0; space < bindings_.size(); ++space) {
        sets.push_back({layouts[space], bindings_[space]});
    }
    return sets;
}

template <typename Self>
std::vector<rhi::BindingSetItem> PassBindings<Self>::writeBindings() const {
    std::vector<rhi::BindingSetItem> writes;
    for (const auto& space : bindings_) {
        for (const rhi::BindingSetItem& item : space) {
            if (rhi::isWriteBinding(item.type)) {
                writes.push_back(item);
            }
        }
    }
    return writes;
}

template class PassBindings<ComputePass>;
template class PassBindings<RasterPass>;

// Errors of pipeline creation (a binding the kernel does not find) name the pass too.
template <typename Create>
decltype(auto) namingPass(const std::string& pass, Create&& create) {
    try {
        return create();
    } catch (const rhi::Error& e) {
        throw rhi::Error("pass '" + pass + "': " + e.what());
    }
}

void ComputePass::record(auto&& issue) {
    const auto& entry = namingPass(
        name_, [&]() -> const auto& {
            return frame_.pipelines().compute(kernel_, bindings_, uint32_t(pushConstants_.size()));
        });
    rhi::ICommandList& commands = frame_.commands();
    commands.beginTimer(name_);
    commands.setComputeState({entry.pipeline, bindingSets(entry.layouts)});
    if (!pushConstants_.empty()) {
        commands.setPushConstants(pushConstants_.data(), uint32_t(pushConstants_.size()));
    }
    issue(commands);
    commands.endTimer();
    if (FiniteCheck* check = frame_.finiteCheck()) {
        check->afterPass(frame_, name_, writeBindings(), {});
    }
}

void ComputePass::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
    record([&](rhi::ICommandList& commands) { commands.dispatch(groupsX, groupsY, groupsZ); });
}

void ComputePass::dispatchThreads(uint32_t x, uint32_t y, uint32_t z, std::array<uint32_t, 3> groupSize) {
    auto groups = [](uint32_t count, uint32_t size) { return (count + size - 1) / size; };
    dispatch(groups(x, groupSize[0]), groups(y, groupSize[1]), groups(z, groupSize[2]));
}

void ComputePass::dispatchIndirect(rhi::IBuffer& args, uint64_t offset) {
    record([&](rhi::ICommandList& commands) { commands.dispatchIndirect(args, offset); });
}

void RasterPass::draw(const std::vector<RasterDraw>& draws, bool indexed) {
    if (draws.empty()) {
        return;
    }
    const uint32_t pushBytes = draws.front().constantBytes;
    for (const RasterDraw& draw : draws) {
        if (draw.constantBytes != pushBytes) {
            throw rhi::Error("pass '" + name_ + "': draws with different push-constant sizes");
        }
    }
    std::vector<rhi::Format> colorFormats;
    for (const rhi::Attachment& color : colors_) {
        colorFormats.push_back(color.texture->desc().format);
    }
    const rhi::Format depthFormat = depth_ ? depth_->texture->desc().format : rhi::Format::Unknown;
    const auto& entry = namingPass(
        name_, [&]() -> const auto& {
            return frame_.pipelines().graphics(vertexKernel_, pixelKernel_, bindings_, pushBytes, state_,
                                               colorFormats, depthFormat);
        });
    rhi::GraphicsState graphics;
    graphics.pipeline = entry.pipeline;
    graphics.colorAttachments = colors_;
    graphics.depthAttachment = depth_;
    graphics.bindings = bindingSets(entry.layouts);
    graphics.viewport = viewport_;
    graphics.indexBuffer = index_;

    rhi::ICommandList& commands = frame_.commands();
    commands.beginTimer(name_);
    commands.setGraphicsState(graphics);
    for (const RasterDraw& draw : draws) {
        if (pushBytes != 0) {
            commands.setPushConstants(draw.constants.data(), pushBytes);
        }
        indexed ? commands.drawIndexed(draw.args) : commands.draw(draw.args);
    }
    commands.endTimer();
    if (FiniteCheck* check = frame_.finiteCheck()) {
        check->afterPass(frame_, name_, writeBindings(), colors_);
    }
}

} // namespace lumina::gi
