// Platform surfaces. Xlib, not XCB: GLFW's X11 windows are Xlib windows, and Xlib's Display
// is what glfwGetX11Display returns; Wayland sessions run GLFW through XWayland.
#include "rhi_vulkan/vk_swapchain_surface.h"

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <vulkan/vulkan_win32.h>
#include <windows.h>
#else
#include <X11/Xlib.h>
#include <vulkan/vulkan_xlib.h>
#endif

#include "rhi/error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_struct.h"

namespace lumina::vulkan {

std::vector<const char*> presentationExtensions() {
#if defined(_WIN32)
    return {VK_KHR_SURFACE_EXTENSION_NAME, VK_KHR_WIN32_SURFACE_EXTENSION_NAME};
#else
    return {VK_KHR_SURFACE_EXTENSION_NAME, VK_KHR_XLIB_SURFACE_EXTENSION_NAME};
#endif
}

VkSurfaceKHR createSurface(VkInstance instance, const rhi::NativeWindow& window) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
#if defined(_WIN32)
    if (window.platform != rhi::NativeWindow::Platform::Win32 || window.window == 0) {
        throw rhi::Error("Vulkan swapchain: this Windows build presents to Win32 windows (HWND) only");
    }
    auto info = vkStruct<VkWin32SurfaceCreateInfoKHR>(VK_STRUCTURE_TYPE_WIN32_SURFACE_CREATE_INFO_KHR);
    info.hinstance = static_cast<HINSTANCE>(window.display ? window.display : GetModuleHandleW(nullptr));
    info.hwnd = reinterpret_cast<HWND>(window.window);
    check(vkCreateWin32SurfaceKHR(instance, &info, nullptr, &surface), "vkCreateWin32SurfaceKHR");
#else
    if (window.platform != rhi::NativeWindow::Platform::Xlib || window.display == nullptr ||
        window.window == 0) {
        throw rhi::Error("Vulkan swapchain: this Linux build presents to X11 (Xlib) windows only");
    }
    auto info = vkStruct<VkXlibSurfaceCreateInfoKHR>(VK_STRUCTURE_TYPE_XLIB_SURFACE_CREATE_INFO_KHR);
    info.dpy = static_cast<Display*>(window.display);
    info.window = static_cast<Window>(window.window);
    check(vkCreateXlibSurfaceKHR(instance, &info, nullptr, &surface), "vkCreateXlibSurfaceKHR");
#endif
    return surface;
}

} // namespace lumina::vulkan
