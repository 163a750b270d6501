#pragma once
// VkResult to exceptions: every failing call throws rhi::Error naming the call, the result
// and what it was working on; VK_ERROR_DEVICE_LOST throws rhi::DeviceLostError.
#include <string_view>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

std::string_view resultName(VkResult result);

// Throws for negative results (errors); success and status codes (VK_TIMEOUT,
// VK_INCOMPLETE, ...) return normally, for the caller to look at.
void check(VkResult result, std::string_view call, std::string_view context = {});

} // namespace lumina::vulkan
