#pragma once
#include "rhi/resource.h"

#include <memory>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

// A VkBuffer with its own memory. Upload and Readback buffers stay mapped for their lifetime.
class Buffer final : public rhi::IBuffer, public std::enable_shared_from_this<Buffer> {
public:
    Buffer(std::shared_ptr<Context> context, const rhi::BufferDesc& desc);
    ~Buffer() override;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    const rhi::BufferDesc& desc() const override { return desc_; }
    void* map() override;

    VkBuffer handle() const { return buffer_; }

private:
    std::shared_ptr<Context> context_;
    rhi::BufferDesc desc_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memorySize_ = 0;
    void* mapped_ = nullptr;
};

} // namespace lumina::vulkan
