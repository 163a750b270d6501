#include "rhi/transfer.h"

#include <algorithm>
#include <cstring>

namespace lumina::rhi {

namespace {
void submitAndWait(IDevice& device, ICommandList& list) {
    IQueue& queue = device.queue(list.queueType());
    queue.waitForValue(queue.submit(list));
}
} // namespace

BufferHandle createBufferWithData(IDevice& device, BufferDesc desc, const void* data, uint64_t size) {
    desc.size = std::max(desc.size, size);
    BufferHandle buffer = device.createBuffer(desc);
    CommandListHandle list = device.createCommandList();
    list->begin();
    list->writeBuffer(*buffer, data, size);
    list->end();
    submitAndWait(device, *list);
    return buffer;
}

std::vector<uint8_t> readBuffer(IDevice& device, IBuffer& buffer) {
    const uint64_t size = buffer.desc().size;
    BufferHandle staging = device.createBuffer(
        {.size = size, .memory = MemoryType::Readback, .debugName = "readback of " + buffer.debugName()});
    CommandListHandle list = device.createCommandList();
    list->begin();
    list->copyBuffer(*staging, 0, buffer, 0, size);
    list->end();
    submitAndWait(device, *list);
    std::vector<uint8_t> out(size);
    std::memcpy(out.data(), staging->map(), size);
    return out;
}

std::vector<uint8_t> readTexture(IDevice& device, ITexture& texture, TextureSlice slice) {
    const TextureDesc& desc = texture.desc();
    const uint32_t width = mipExtent(desc.width, slice.mipLevel);
    const uint32_t height = mipExtent(desc.height, slice.mipLevel);
    const uint32_t depth = desc.dimension == TextureDimension::Texture3D ? mipExtent(desc.depth, slice.mipLevel) : 1;
    const uint32_t pitch = alignedRowPitch(width, desc.format);
    const uint32_t packedRow = width * formatInfo(desc.format).bytesPerTexel;

    BufferHandle staging = device.createBuffer({.size = uint64_t(pitch) * height * depth,
                                                .memory = MemoryType::Readback,
                                                .debugName = "readback of " + texture.debugName()});
    CommandListHandle list = device.createCommandList();
    list->begin();
    list->copyTextureToBuffer(*staging, 0, pitch, texture, slice);
    list->end();
    submitAndWait(device, *list);

    std::vector<uint8_t> out(size_t(packedRow) * height * depth);
    const auto* src = static_cast<const uint8_t*>(staging->map());
    for (uint32_t row = 0; row < height * depth; ++row) {
        std::memcpy(out.data() + size_t(row) * packedRow, src + size_t(row) * pitch, packedRow);
    }
    return out;
}

void writeTexture(IDevice& device, ITexture& texture, TextureSlice slice, const void* data) {
    CommandListHandle list = device.createCommandList();
    list->begin();
    list->writeTexture(texture, slice, data);
    list->end();
    submitAndWait(device, *list);
}

} // namespace lumina::rhi
