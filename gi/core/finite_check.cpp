#include "gi/core/finite_check.h"

#include "gi/core/frame_context.h"
#include "rhi/transfer.h"
#include "shaders/debug/finite_check_shared.h"

#include <stdexcept>

namespace lumina::gi {

namespace {

bool holdsFloats(rhi::Format format) {
    return rhi::formatInfo(format).kind == rhi::FormatKind::Float;
}

std::string nameOf(const std::string& debugName) {
    return debugName.empty() ? std::string("(unnamed)") : "'" + debugName + "'";
}

uint32_t groups(uint32_t count, uint32_t size) {
    return (count + size - 1) / size;
}

} // namespace

std::string NonFiniteWrite::describe() const {
    return "frame " + std::to_string(frame) + ": pass '" + pass + "' wrote " + std::to_string(count) +
           " non-finite value(s) (NaN or Inf) to " + resource;
}

FiniteCheck::FiniteCheck(rhi::IDevice& device, uint32_t maxChecksPerFrame)
    : device_(device), maxChecks_(maxChecksPerFrame),
      counts_(device.createBuffer({.size = uint64_t(maxChecksPerFrame) * sizeof(uint32_t),
                                   .structStride = sizeof(uint32_t),
                                   .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                   .debugName = "finite check: counts"})) {}

void FiniteCheck::watchBuffer(const rhi::IBuffer& buffer) {
    if (buffer.desc().structStride != sizeof(gpu::float4)) {
        throw std::invalid_argument("finite check: buffer " + nameOf(buffer.desc().debugName) +
                                    " has a stride of " + std::to_string(buffer.desc().structStride) +
                                    " bytes; only buffers of float4 (16) can be watched");
    }
    watched_.insert(&buffer);
}

void FiniteCheck::beginFrame(FrameContext& frame) {
    checks_.clear();
    frameIndex_ = frame.frameIndex();
    frame.commands().fillBuffer(*counts_, 0u);
    frame.setFiniteCheck(this);
}

void FiniteCheck::afterPass(FrameContext& frame, std::string_view pass,
                            const std::vector<rhi::BindingSetItem>& writes,
                            const std::vector<rhi::Attachment>& colorTargets) {
    for (const rhi::BindingSetItem& item : writes) {
        if (item.type == rhi::BindingType::TextureUAV) {
            checkTexture(frame, pass, item.texture, item.subresources.baseMip);
        } else if (item.buffer && watched_.count(item.buffer.get()) != 0) {
            checkBuffer(frame, pass, item.buffer);
        }
    }
    for (const rhi::Attachment& color : colorTargets) {
        checkTexture(frame, pass, color.texture, color.mipLevel);
    }
}

void FiniteCheck::checkTexture(FrameContext& frame, std::string_view pass, const rhi::TextureHandle& texture,
                               uint32_t mip) {
    const rhi::TextureDesc& desc = texture->desc();
    if (!holdsFloats(desc.format) || !hasFlag(desc.usage, rhi::TextureUsage::Sampled) ||
        rhi::isCubeDimension(desc.dimension)) {
        return;
    }
    const uint32_t width = rhi::mipExtent(desc.width, mip);
    const uint32_t height = rhi::mipExtent(desc.height, mip);
    std::string resource = "texture " + nameOf(desc.debugName) + (mip ? " mip " + std::to_string(mip) : "");
    checks_.push_back({std::string(pass), std::move(resource)});
    const rhi::BindingSetItem read = rhi::BindingSetItem::sampledTexture(0, texture);
    switch (desc.dimension) {
    case rhi::TextureDimension::Texture2D:
        dispatch(frame, "debug/finite_check.texture2d", read, {width, height, 1, mip},
                 {LUMINA_FINITE_CHECK_GROUP_2D, LUMINA_FINITE_CHECK_GROUP_2D, 1});
        break;
    case rhi::TextureDimension::Texture2DArray: {
        rhi::BindingSetItem array = read;
        array.reg = 1;
        dispatch(frame, "debug/finite_check.texture2dArray", array, {width, height, desc.arrayLayers, mip},
                 {LUMINA_FINITE_CHECK_GROUP_2D, LUMINA_FINITE_CHECK_GROUP_2D, 1});
        break;
    }
    case rhi::TextureDimension::Texture3D: {
        rhi::BindingSetItem volume = read;
        volume.reg = 2;
        dispatch(frame, "debug/finite_check.texture3d", volume,
                 {width, height, rhi::mipExtent(desc.depth, mip), mip},
                 {LUMINA_FINITE_CHECK_GROUP_3D, LUMINA_FINITE_CHECK_GROUP_3D, LUMINA_FINITE_CHECK_GROUP_3D});
        break;
    }
    default:
        break;
    }
}

void FiniteCheck::checkBuffer(FrameContext& frame, std::string_view pass, const rhi::BufferHandle& buffer) {
    checks_.push_back({std::string(pass), "buffer " + nameOf(buffer->desc().debugName)});
    const auto elements = uint32_t(buffer->desc().size / sizeof(gpu::float4));
    dispatch(frame, "debug/finite_check.buffer", rhi::BindingSetItem::structuredBuffer(3, buffer),
             {elements, 1, 1, 0}, {LUMINA_FINITE_CHECK_GROUP_1D, 1, 1});
}

// Recorded straight into the command list, not through frame.compute(): a check is no pass of
// its own (no timer, and no check of the check).
void FiniteCheck::dispatch(FrameContext& frame, std::string_view kernel, rhi::BindingSetItem resource,
                           std::array<uint32_t, 4> extent, std::array<uint32_t, 3> groupSize) {
    const uint32_t slot = uint32_t(checks_.size() - 1);
    if (slot >= maxChecks_) {
        throw std::runtime_error("finite check: more than " + std::to_string(maxChecks_) +
                                 " resources written in one frame; raise FiniteCheck's maxChecksPerFrame");
    }
    const SpaceBindings bindings = {
        {std::move(resource), rhi::BindingSetItem::rwStructuredBuffer(0, counts_)}};
    const gpu::FiniteCheckConstants constants{.extent = {extent[0], extent[1], extent[2], extent[3]},
                                              .slot = {slot, 0u, 0u, 0u}};
    const auto& entry = frame.pipelines().compute(kernel, bindings, sizeof(constants));
    rhi::ICommandList& commands = frame.commands();
    commands.setComputeState({entry.pipeline, {{entry.layouts[0], bindings[0]}}});
    commands.setPushConstants(&constants, sizeof(constants));
    commands.dispatch(groups(extent[0], groupSize[0]), groups(extent[1], groupSize[1]),
                      groups(extent[2], groupSize[2]));
}

std::optional<NonFiniteWrite> FiniteCheck::report() {
    if (checks_.empty()) {
        return std::nullopt;
    }
    const std::vector<uint32_t> counts = rhi::readBufferAs<uint32_t>(device_, *counts_);
    for (size_t i = 0; i < checks_.size(); ++i) {
        if (counts[i] != 0) {
            return NonFiniteWrite{frameIndex_, checks_[i].pass, checks_[i].resource, counts[i]};
        }
    }
    return std::nullopt;
}

} // namespace lumina::gi
