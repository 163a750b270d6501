#pragma once
// The one place that knows window systems on Vulkan: which instance extensions presenting
// needs on this platform, and a VkSurfaceKHR from an rhi::NativeWindow.
#include "rhi/swapchain.h"

#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

// VK_KHR_surface and the platform's surface extension (Xlib on Linux, Win32 on Windows).
std::vector<const char*> presentationExtensions();

// Throws rhi::Error naming the platform when the window is not one this build can present to.
VkSurfaceKHR createSurface(VkInstance instance, const rhi::NativeWindow& window);

} // namespace lumina::vulkan
