#pragma once
// rhi::Format to VkFormat and image aspects.
#include "rhi/format.h"

#include <vulkan/vulkan.h>

namespace lumina::vulkan {

// Throws rhi::Error for Format::Unknown or an out-of-range value.
VkFormat toVkFormat(rhi::Format format);
VkImageAspectFlags aspectMask(rhi::Format format);

} // namespace lumina::vulkan
