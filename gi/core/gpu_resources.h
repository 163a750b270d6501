#pragma once
// The two kinds of GPU memory GI passes make most: a structured buffer they read and write, and a
// 2D texture they write as storage and read sampled. Names carry their subsystem
// ("screen probes: rays"), as validation messages and captures show them.
#include "rhi/rhi.h"

#include <cstdint>
#include <string>

namespace lumina::gi {

inline rhi::BufferHandle createStructuredBuffer(rhi::IDevice& device, uint64_t count, uint32_t stride,
                                                const std::string& name) {
    return device.createBuffer({.size = count * stride,
                                .structStride = stride,
                                .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                .debugName = name});
}

inline rhi::TextureHandle createStorageTexture2d(rhi::IDevice& device, rhi::Format format, uint32_t width,
                                                 uint32_t height, const std::string& name) {
    return device.createTexture({.format = format,
                                 .width = width,
                                 .height = height,
                                 .usage = rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled,
                                 .debugName = name});
}

} // namespace lumina::gi
