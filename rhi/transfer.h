#pragma once
// Blocking conveniences for tools and tests: fill a resource from host memory, or read
// one back, on the graphics queue. Frame code records copies on its own command lists.
#include <cstdint>
#include <vector>

#include "rhi/device.h"

namespace lumina::rhi {

// A GPU-only buffer filled with `data`.
BufferHandle createBufferWithData(IDevice& device, BufferDesc desc, const void* data, uint64_t size);

std::vector<uint8_t> readBuffer(IDevice& device, IBuffer& buffer);

// Tightly packed rows of one mip of one layer (every depth slice of a 3D texture).
std::vector<uint8_t> readTexture(IDevice& device, ITexture& texture, TextureSlice slice = {});

void writeTexture(IDevice& device, ITexture& texture, TextureSlice slice, const void* data);

template <typename T>
std::vector<T> readBufferAs(IDevice& device, IBuffer& buffer) {
    const std::vector<uint8_t> bytes = readBuffer(device, buffer);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::copy_n(bytes.data(), out.size() * sizeof(T), reinterpret_cast<uint8_t*>(out.data()));
    return out;
}

} // namespace lumina::rhi
