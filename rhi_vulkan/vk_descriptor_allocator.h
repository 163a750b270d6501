#pragma once
// Descriptor sets that live for one recording of one command list: allocated per bind from
// pools the list owns, all freed at once when the list begins again.
#include <memory>
#include <string_view>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

class DescriptorAllocator {
public:
    explicit DescriptorAllocator(std::shared_ptr<Context> context) : context_(std::move(context)) {}
    ~DescriptorAllocator();
    DescriptorAllocator(const DescriptorAllocator&) = delete;
    DescriptorAllocator& operator=(const DescriptorAllocator&) = delete;

    // Adds a pool when the current ones are full.
    VkDescriptorSet allocate(VkDescriptorSetLayout layout, std::string_view debugName);
    // Only once the GPU is done with every set allocated so far.
    void reset();

private:
    VkDescriptorPool createPool();

    std::shared_ptr<Context> context_;
    std::vector<VkDescriptorPool> pools_;
    size_t current_ = 0;
};

} // namespace lumina::vulkan
