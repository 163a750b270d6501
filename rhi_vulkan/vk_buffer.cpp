#include "rhi_vulkan/vk_buffer.h"

#include "rhi/error.h"
#include "rhi/validation.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <string>

namespace lumina::vulkan {

namespace {

VkBufferUsageFlags usageFlags(rhi::BufferUsage usage) {
    using U = rhi::BufferUsage;
    // Copies to and from every buffer are always allowed (rhi/resource.h).
    VkBufferUsageFlags flags = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (hasFlag(usage, U::Constant)) {
        flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    }
    if (hasFlag(usage, U::Structured) || hasFlag(usage, U::Raw) || hasFlag(usage, U::Storage)) {
        flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    }
    if (hasFlag(usage, U::Index)) {
        flags |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    }
    if (hasFlag(usage, U::Indirect)) {
        flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    }
    return flags;
}

} // namespace

Buffer::Buffer(std::shared_ptr<Context> context, const rhi::BufferDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateBufferDesc(desc_);
    context_->checkAllocationSize(desc_.size, desc_.debugName);
    const VkDevice device = context_->device();
    auto info = vkStruct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = desc_.size;
    info.usage = usageFlags(desc_.usage);
    const auto& families = context_->queueFamilies();
    info.sharingMode = families.size() > 1 ? VK_SHARING_MODE_CONCURRENT : VK_SHARING_MODE_EXCLUSIVE;
    info.queueFamilyIndexCount = families.size() > 1 ? static_cast<uint32_t>(families.size()) : 0;
    info.pQueueFamilyIndices = families.data();
    check(vkCreateBuffer(device, &info, nullptr, &buffer_), "vkCreateBuffer", desc_.debugName);
    context_->setName(VK_OBJECT_TYPE_BUFFER, buffer_, desc_.debugName);

    try {
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(device, buffer_, &requirements);
        memory_ = context_->allocateMemory(requirements, desc_.memory, desc_.debugName);
        memorySize_ = requirements.size;
        check(vkBindBufferMemory(device, buffer_, memory_, 0), "vkBindBufferMemory", desc_.debugName);
        if (desc_.memory != rhi::MemoryType::GpuOnly) {
            check(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory",
                  desc_.debugName);
        }
    } catch (...) {
        context_->freeMemory(memory_, memorySize_);
        vkDestroyBuffer(device, buffer_, nullptr);
        throw;
    }
}

Buffer::~Buffer() {
    vkDestroyBuffer(context_->device(), buffer_, nullptr);
    context_->freeMemory(memory_, memorySize_); // unmaps implicitly
}

void* Buffer::map() {
    if (!mapped_) {
        throw rhi::Error("map: buffer '" + desc_.debugName +
                         "' is GpuOnly; only Upload and Readback buffers are host-visible");
    }
    return mapped_;
}

} // namespace lumina::vulkan
