#pragma once
#include "rhi/resource.h"

#include <memory>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

class Sampler final : public rhi::ISampler {
public:
    Sampler(std::shared_ptr<Context> context, const rhi::SamplerDesc& desc);
    ~Sampler() override;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    const rhi::SamplerDesc& desc() const override { return desc_; }
    VkSampler handle() const { return sampler_; }

private:
    std::shared_ptr<Context> context_;
    rhi::SamplerDesc desc_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

VkCompareOp toVkCompareOp(rhi::CompareOp op);

} // namespace lumina::vulkan
