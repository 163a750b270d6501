// Copies, uploads, fills and clears.
#include "rhi/error.h"
#include "rhi/validation.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_command_list.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_texture.h"

#include <cstring>
#include <string>

namespace lumina::vulkan {

namespace {

using S = rhi::ResourceState;

// Uploads are placed at offsets valid for any texel size and for depth copies (4 bytes).
constexpr uint64_t kUploadAlignment = 16;

VkImageSubresourceLayers subresource(const Texture& texture, rhi::TextureSlice slice, const char* command) {
    rhi::validateTextureSlice(command, texture, slice);
    return {texture.aspect(), slice.mipLevel, slice.arrayLayer, 1};
}

uint64_t texelBytes(const Texture& texture) {
    return rhi::formatInfo(texture.desc().format).bytesPerTexel;
}

// The buffer side of a buffer <-> texture copy: rows `rowPitch` apart, slices of a 3D
// texture one after another (the rules: rhi::validateBufferTextureCopy). The RHI's offset
// and pitch alignments are multiples of every texel size, as Vulkan requires.
VkBufferImageCopy bufferImageCopy(const Texture& texture, rhi::TextureSlice slice, const Buffer& buffer,
                                  uint64_t offset, uint32_t rowPitch, const char* command) {
    rhi::validateBufferTextureCopy(command, texture, slice, buffer, offset, rowPitch);
    const VkImageSubresourceLayers layers = subresource(texture, slice, command);
    const VkExtent3D extent = texture.mipExtent(slice.mipLevel);
    const uint64_t texel = texelBytes(texture);
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.bufferRowLength = static_cast<uint32_t>(rowPitch / texel);
    region.bufferImageHeight = extent.height;
    region.imageSubresource = layers;
    region.imageExtent = extent;
    return region;
}

VkImageSubresourceRange wholeTexture(const Texture& texture) {
    return texture.fullRange();
}

} // namespace

void CommandList::copyBuffer(rhi::IBuffer& dst, uint64_t dstOffset, rhi::IBuffer& src, uint64_t srcOffset,
                             uint64_t size) {
    requireRecording("copyBuffer");
    Buffer& to = buffer(dst, "copyBuffer");
    Buffer& from = buffer(src, "copyBuffer");
    rhi::validateBufferRange("copyBuffer (source)", from, srcOffset, size);
    rhi::validateBufferRange("copyBuffer (destination)", to, dstOffset, size);
    prepare([&] {
        require(to, S::CopyDest);
        require(from, S::CopySource);
    });
    const VkBufferCopy region{srcOffset, dstOffset, size};
    vkCmdCopyBuffer(commandBuffer_, from.handle(), to.handle(), 1, &region);
    finishCommand();
}

void CommandList::copyBufferToTexture(rhi::ITexture& dst, rhi::TextureSlice slice, rhi::IBuffer& src,
                                      uint64_t srcOffset, uint32_t rowPitch) {
    requireRecording("copyBufferToTexture");
    Texture& to = texture(dst, "copyBufferToTexture");
    Buffer& from = buffer(src, "copyBufferToTexture");
    const VkBufferImageCopy region =
        bufferImageCopy(to, slice, from, srcOffset, rowPitch, "copyBufferToTexture");
    prepare([&] {
        require(to, S::CopyDest);
        require(from, S::CopySource);
    });
    vkCmdCopyBufferToImage(commandBuffer_, from.handle(), to.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    finishCommand();
}

void CommandList::copyTextureToBuffer(rhi::IBuffer& dst, uint64_t dstOffset, uint32_t rowPitch,
                                      rhi::ITexture& src, rhi::TextureSlice slice) {
    requireRecording("copyTextureToBuffer");
    Buffer& to = buffer(dst, "copyTextureToBuffer");
    Texture& from = texture(src, "copyTextureToBuffer");
    const VkBufferImageCopy region =
        bufferImageCopy(from, slice, to, dstOffset, rowPitch, "copyTextureToBuffer");
    prepare([&] {
        require(to, S::CopyDest);
        require(from, S::CopySource);
    });
    vkCmdCopyImageToBuffer(commandBuffer_, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                           1, &region);
    finishCommand();
}

void CommandList::copyTexture(rhi::ITexture& dst, rhi::TextureSlice dstSlice, rhi::ITexture& src,
                              rhi::TextureSlice srcSlice) {
    requireRecording("copyTexture");
    Texture& to = texture(dst, "copyTexture");
    Texture& from = texture(src, "copyTexture");
    rhi::validateTextureCopy(to, dstSlice, from, srcSlice);
    VkImageCopy region{};
    region.srcSubresource = subresource(from, srcSlice, "copyTexture");
    region.dstSubresource = subresource(to, dstSlice, "copyTexture");
    region.extent = from.mipExtent(srcSlice.mipLevel);
    prepare([&] {
        require(to, S::CopyDest);
        require(from, S::CopySource);
    });
    vkCmdCopyImage(commandBuffer_, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    finishCommand();
}

void CommandList::writeBuffer(rhi::IBuffer& dst, const void* data, uint64_t size, uint64_t dstOffset) {
    requireRecording("writeBuffer");
    Buffer& to = buffer(dst, "writeBuffer");
    rhi::validateBufferRange("writeBuffer", to, dstOffset, size);
    if (size == 0) {
        return;
    }
    const UploadRing::Allocation staging = upload_.allocate(size, kUploadAlignment);
    std::memcpy(staging.data, data, size);
    prepare([&] { require(to, S::CopyDest); });
    const VkBufferCopy region{staging.offset, dstOffset, size};
    vkCmdCopyBuffer(commandBuffer_, staging.buffer, to.handle(), 1, &region);
    finishCommand();
}

void CommandList::writeTexture(rhi::ITexture& dst, rhi::TextureSlice slice, const void* data) {
    requireRecording("writeTexture");
    Texture& to = texture(dst, "writeTexture");
    const VkImageSubresourceLayers layers = subresource(to, slice, "writeTexture");
    const VkExtent3D extent = to.mipExtent(slice.mipLevel);
    const uint64_t size = texelBytes(to) * extent.width * extent.height * extent.depth;
    const UploadRing::Allocation staging = upload_.allocate(size, kUploadAlignment);
    std::memcpy(staging.data, data, size);
    prepare([&] { require(to, S::CopyDest); });
    VkBufferImageCopy region{};
    region.bufferOffset = staging.offset; // row length 0: rows tightly packed
    region.imageSubresource = layers;
    region.imageExtent = extent;
    vkCmdCopyBufferToImage(commandBuffer_, staging.buffer, to.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    finishCommand();
}

void CommandList::fillBuffer(rhi::IBuffer& dst, uint32_t value) {
    requireRecording("fillBuffer");
    Buffer& to = buffer(dst, "fillBuffer");
    prepare([&] { require(to, S::CopyDest); });
    // Whole size: Vulkan fills whole 4-byte words, a trailing partial word stays as it was.
    vkCmdFillBuffer(commandBuffer_, to.handle(), 0, VK_WHOLE_SIZE, value);
    finishCommand();
}

void CommandList::clearColor(rhi::ITexture& target, std::array<float, 4> value) {
    requireRecording("clearColor");
    Texture& texture = this->texture(target, "clearColor");
    const rhi::FormatInfo& format = rhi::formatInfo(texture.desc().format);
    if (format.kind == rhi::FormatKind::Depth) {
        throw rhi::Error("clearColor: texture '" + texture.debugName() +
                         "' has a depth format; use clearDepth");
    }
    VkClearColorValue clear{};
    for (int channel = 0; channel < 4; ++channel) {
        if (format.kind == rhi::FormatKind::Uint) {
            clear.uint32[channel] = static_cast<uint32_t>(value[channel]); // the value, not its bits
        } else {
            clear.float32[channel] = value[channel];
        }
    }
    prepare([&] { require(texture, S::CopyDest); });
    const VkImageSubresourceRange range = wholeTexture(texture);
    vkCmdClearColorImage(commandBuffer_, texture.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1,
                         &range);
    finishCommand();
}

void CommandList::clearColorUint(rhi::ITexture& target, std::array<uint32_t, 4> value) {
    requireRecording("clearColorUint");
    Texture& texture = this->texture(target, "clearColorUint");
    if (rhi::isDepthFormat(texture.desc().format)) {
        throw rhi::Error("clearColorUint: texture '" + texture.debugName() +
                         "' has a depth format; use clearDepth");
    }
    // Integer formats take the values; on float formats the 32-bit patterns are written as
    // they are (like D3D12's ClearUnorderedAccessViewUint on 32-bit formats).
    VkClearColorValue clear{};
    for (int channel = 0; channel < 4; ++channel) {
        clear.uint32[channel] = value[channel];
    }
    prepare([&] { require(texture, S::CopyDest); });
    const VkImageSubresourceRange range = wholeTexture(texture);
    vkCmdClearColorImage(commandBuffer_, texture.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1,
                         &range);
    finishCommand();
}

void CommandList::clearDepth(rhi::ITexture& target, float depth) {
    requireRecording("clearDepth");
    Texture& texture = this->texture(target, "clearDepth");
    if (!hardware_->supportsGraphics) {
        // vkCmdClearDepthStencilImage needs a graphics queue.
        throw rhi::Error("clearDepth of texture '" + texture.debugName() + "': not on a compute-only queue");
    }
    if (!rhi::isDepthFormat(texture.desc().format)) {
        throw rhi::Error("clearDepth: texture '" + texture.debugName() + "' has no depth format");
    }
    prepare([&] { require(texture, S::CopyDest); });
    const VkClearDepthStencilValue clear{depth, 0};
    const VkImageSubresourceRange range = wholeTexture(texture);
    vkCmdClearDepthStencilImage(commandBuffer_, texture.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                &clear, 1, &range);
    finishCommand();
}

} // namespace lumina::vulkan
