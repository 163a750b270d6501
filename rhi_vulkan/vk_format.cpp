#include "rhi_vulkan/vk_format.h"

#include "rhi/error.h"

#include <string>

namespace lumina::vulkan {

VkFormat toVkFormat(rhi::Format format) {
    switch (format) {
    case rhi::Format::R8_UNORM:
        return VK_FORMAT_R8_UNORM;
    case rhi::Format::RGBA8_UNORM:
        return VK_FORMAT_R8G8B8A8_UNORM;
    case rhi::Format::RGBA8_SRGB:
        return VK_FORMAT_R8G8B8A8_SRGB;
    case rhi::Format::R16_FLOAT:
        return VK_FORMAT_R16_SFLOAT;
    case rhi::Format::RG16_FLOAT:
        return VK_FORMAT_R16G16_SFLOAT;
    case rhi::Format::RGBA16_FLOAT:
        return VK_FORMAT_R16G16B16A16_SFLOAT;
    case rhi::Format::R32_FLOAT:
        return VK_FORMAT_R32_SFLOAT;
    case rhi::Format::RG32_FLOAT:
        return VK_FORMAT_R32G32_SFLOAT;
    case rhi::Format::RGBA32_FLOAT:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case rhi::Format::R32_UINT:
        return VK_FORMAT_R32_UINT;
    case rhi::Format::RG32_UINT:
        return VK_FORMAT_R32G32_UINT;
    case rhi::Format::RGBA32_UINT:
        return VK_FORMAT_R32G32B32A32_UINT;
    case rhi::Format::D32_FLOAT:
        return VK_FORMAT_D32_SFLOAT;
    case rhi::Format::Unknown:
    case rhi::Format::Count:
        break;
    }
    throw rhi::Error("no Vulkan format for rhi::Format " + std::to_string(static_cast<int>(format)));
}

VkImageAspectFlags aspectMask(rhi::Format format) {
    return rhi::isDepthFormat(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

} // namespace lumina::vulkan
