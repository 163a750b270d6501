#pragma once
// Presenting to a window. The RHI names no window system: the application hands the backend
// a platform window handle (NativeWindow, filled by app/viewer from GLFW), and the backend
// makes its surface from it (VK_KHR_xlib_surface / VK_KHR_win32_surface on Vulkan, a DXGI
// flip-model swapchain on the HWND on D3D12).
//
// The application never draws into the swapchain's images. It renders a frame into a texture
// of its own (RGBA8_UNORM, RenderTarget | Sampled, the swapchain's size) and hands it to
// present(), which copies it into the next image on the graphics queue after everything
// submitted before it, then presents. That keeps the swapchain's image format (BGRA on most
// Vulkan surfaces), its acquire/present semaphores and its per-image states inside the backend,
// and lets the same texture be read back for a screenshot.
//
//   auto swapchain = device->createSwapchain({.window = native, .width = w, .height = h});
//   list->transition(*image, rhi::ResourceState::CopySource);   // last command of the frame
//   queue.submit(*list);
//   swapchain->present(*image);                                  // Suboptimal: resize() it
#include "rhi/resource.h"

#include <cstdint>
#include <memory>

namespace lumina::rhi {

// A native window, as the platform layer knows it. Only the backends that present look inside.
struct NativeWindow {
    enum class Platform : uint8_t { Unknown, Win32, Xlib };
    Platform platform = Platform::Unknown;
    void* display = nullptr; // Xlib: Display*; Win32: HINSTANCE (may be null)
    uint64_t window = 0;     // Xlib: Window (an XID); Win32: HWND
};

struct SwapchainDesc {
    NativeWindow window;
    uint32_t width = 0; // the window's framebuffer size in pixels; 0 x 0 while minimised
    uint32_t height = 0;
    bool vsync = true;           // true: wait for vertical blank (FIFO); false: present at once
    uint32_t framesInFlight = 2; // 2 or 3: presents the CPU may queue before it waits
};

enum class PresentResult : uint8_t {
    Presented,
    Skipped,    // the swapchain is zero-sized (a minimised window) or was out of date
    Suboptimal, // presented, but the surface changed: call resize() with the window's size
};

class ISwapchain {
public:
    virtual ~ISwapchain() = default;

    virtual uint32_t width() const = 0;
    virtual uint32_t height() const = 0;
    virtual bool vsync() const = 0;

    // Recreates the images for a new framebuffer size (0 x 0: minimised, presents are skipped
    // until a non-zero size comes) and vsync mode. Waits for the swapchain's presents in flight.
    virtual void resize(uint32_t width, uint32_t height, bool vsync) = 0;
    // Copies `image` (RGBA8_UNORM, the swapchain's size, in ResourceState::CopySource after the
    // command lists already submitted) into the next swapchain image and presents it. Waits when
    // framesInFlight presents are still on the GPU.
    virtual PresentResult present(ITexture& image) = 0;
};

using SwapchainHandle = std::unique_ptr<ISwapchain>;

} // namespace lumina::rhi
