#include "rhi_vulkan/vk_sampler.h"

#include "rhi/validation.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <algorithm>

namespace lumina::vulkan {

namespace {

VkFilter toVkFilter(rhi::Filter filter) {
    return filter == rhi::Filter::Point ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode toVkAddressMode(rhi::AddressMode mode) {
    switch (mode) {
    case rhi::AddressMode::Wrap:
        return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case rhi::AddressMode::Clamp:
        return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case rhi::AddressMode::Mirror:
        return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case rhi::AddressMode::Border:
        return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    }
    return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

} // namespace

VkCompareOp toVkCompareOp(rhi::CompareOp op) {
    switch (op) {
    case rhi::CompareOp::Never:
        return VK_COMPARE_OP_NEVER;
    case rhi::CompareOp::Less:
        return VK_COMPARE_OP_LESS;
    case rhi::CompareOp::LessEqual:
        return VK_COMPARE_OP_LESS_OR_EQUAL;
    case rhi::CompareOp::Equal:
        return VK_COMPARE_OP_EQUAL;
    case rhi::CompareOp::GreaterEqual:
        return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case rhi::CompareOp::Greater:
        return VK_COMPARE_OP_GREATER;
    case rhi::CompareOp::NotEqual:
        return VK_COMPARE_OP_NOT_EQUAL;
    case rhi::CompareOp::Always:
        return VK_COMPARE_OP_ALWAYS;
    }
    return VK_COMPARE_OP_ALWAYS;
}

Sampler::Sampler(std::shared_ptr<Context> context, const rhi::SamplerDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateSamplerDesc(desc_);
    auto info = vkStruct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = toVkFilter(desc_.magFilter);
    info.minFilter = toVkFilter(desc_.minFilter);
    info.mipmapMode = desc_.mipFilter == rhi::Filter::Point ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                            : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = toVkAddressMode(desc_.addressU);
    info.addressModeV = toVkAddressMode(desc_.addressV);
    info.addressModeW = toVkAddressMode(desc_.addressW);
    // Anisotropy is a quality hint: devices without it filter isotropically.
    const float maxAnisotropy = std::min(desc_.maxAnisotropy, context_->limits().maxSamplerAnisotropy);
    info.anisotropyEnable = context_->features().samplerAnisotropy && maxAnisotropy > 1.0f;
    info.maxAnisotropy = info.anisotropyEnable ? maxAnisotropy : 1.0f;
    info.compareEnable = desc_.compareEnable;
    info.compareOp = toVkCompareOp(desc_.compareOp);
    info.minLod = 0.0f;
    info.maxLod = VK_LOD_CLAMP_NONE;
    // D3D12's default border colour, so Border sampling matches on both backends.
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    check(vkCreateSampler(context_->device(), &info, nullptr, &sampler_), "vkCreateSampler", desc_.debugName);
    context_->setName(VK_OBJECT_TYPE_SAMPLER, sampler_, desc_.debugName);
}

Sampler::~Sampler() {
    vkDestroySampler(context_->device(), sampler_, nullptr);
}

} // namespace lumina::vulkan
