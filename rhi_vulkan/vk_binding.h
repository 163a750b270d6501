#pragma once
// Binding layouts as descriptor set layouts, and binding sets written into descriptor sets.
// HLSL register n of class b/t/u/s is binding n + 0/100/200/300 (docs/binding.md); the
// register space is the descriptor set index.
#include "rhi/binding.h"

#include <memory>
#include <string_view>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;
class DescriptorAllocator;

// The register shifts the shader build uses (cmake/LuminaShaders.cmake).
constexpr uint32_t kConstantBufferShift = 0;
constexpr uint32_t kShaderResourceShift = 100;
constexpr uint32_t kUnorderedAccessShift = 200;
constexpr uint32_t kSamplerShift = 300;

uint32_t bindingNumber(rhi::BindingType type, uint32_t reg);
VkDescriptorType descriptorType(rhi::BindingType type);
VkShaderStageFlags shaderStages(rhi::ShaderStageMask mask);

class BindingLayout final : public rhi::IBindingLayout {
public:
    BindingLayout(std::shared_ptr<Context> context, const rhi::BindingLayoutDesc& desc);
    ~BindingLayout() override;
    BindingLayout(const BindingLayout&) = delete;
    BindingLayout& operator=(const BindingLayout&) = delete;

    const rhi::BindingLayoutDesc& desc() const override { return desc_; }
    VkDescriptorSetLayout handle() const { return layout_; }

private:
    std::shared_ptr<Context> context_;
    rhi::BindingLayoutDesc desc_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
};

// Allocates a descriptor set for `set.layout` and writes every item into it. Throws, naming
// `user` (the pipeline) and the register, when an item is missing, has no resource, or
// does not fit (usage flags, alignment, range limits).
VkDescriptorSet writeBindingSet(Context& context, DescriptorAllocator& allocator, const rhi::BindingSet& set,
                                std::string_view user);

// The dimension a binding views its texture as: the override if any, else the texture's
// own, except that UAVs see cubes as 2D arrays (HLSL has no RWTextureCube).
rhi::TextureDimension bindingViewDimension(const rhi::BindingSetItem& item);

} // namespace lumina::vulkan
