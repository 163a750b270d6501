#include "rhi_vulkan/vk_descriptor_allocator.h"

#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <string>

namespace lumina::vulkan {

namespace {
// Sized for a frame's worth of passes; further pools are added as needed.
constexpr uint32_t kSetsPerPool = 256;
constexpr VkDescriptorPoolSize kPoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 512}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1024},
    {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1024}, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 512},
    {VK_DESCRIPTOR_TYPE_SAMPLER, 256},
};
} // namespace

DescriptorAllocator::~DescriptorAllocator() {
    for (VkDescriptorPool pool : pools_) {
        vkDestroyDescriptorPool(context_->device(), pool, nullptr);
    }
}

VkDescriptorPool DescriptorAllocator::createPool() {
    auto info = vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    info.maxSets = kSetsPerPool;
    info.poolSizeCount = static_cast<uint32_t>(std::size(kPoolSizes));
    info.pPoolSizes = kPoolSizes;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(context_->device(), &info, nullptr, &pool), "vkCreateDescriptorPool");
    return pool;
}

VkDescriptorSet DescriptorAllocator::allocate(VkDescriptorSetLayout layout, std::string_view debugName) {
    auto info = vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    for (;;) {
        const bool freshPool = current_ == pools_.size();
        if (freshPool) {
            pools_.push_back(createPool());
        }
        info.descriptorPool = pools_[current_];
        const VkResult result = vkAllocateDescriptorSets(context_->device(), &info, &set);
        const bool full = result == VK_ERROR_OUT_OF_POOL_MEMORY || result == VK_ERROR_FRAGMENTED_POOL;
        if (full && !freshPool) {
            ++current_; // this pool is used up: go on to the next, or a new one
            continue;
        }
        // A set that does not fit an empty pool never will: report it.
        check(result, "vkAllocateDescriptorSets", debugName);
        return set;
    }
}

void DescriptorAllocator::reset() {
    for (VkDescriptorPool pool : pools_) {
        vkResetDescriptorPool(context_->device(), pool, 0);
    }
    current_ = 0;
}

} // namespace lumina::vulkan
