#pragma once
// rhi::ISwapchain on Vulkan: a VkSurfaceKHR and VkSwapchainKHR whose images only ever receive
// a copy of the application's frame (rhi/swapchain.h). Per frame in flight: an acquire
// semaphore, a command buffer for the copy and a fence; per image: the semaphore its present
// waits on. Recreated on resize(), and dropped while the window is 0 x 0.
#include "rhi/swapchain.h"

#include <memory>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

class Swapchain final : public rhi::ISwapchain {
public:
    Swapchain(std::shared_ptr<Context> context, const rhi::SwapchainDesc& desc);
    ~Swapchain() override;
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    uint32_t width() const override { return extent_.width; }
    uint32_t height() const override { return extent_.height; }
    bool vsync() const override { return vsync_; }
    void resize(uint32_t width, uint32_t height, bool vsync) override;
    rhi::PresentResult present(rhi::ITexture& image) override;

private:
    struct FrameSlot {
        VkCommandBuffer commands = VK_NULL_HANDLE;
        VkFence done = VK_NULL_HANDLE;
        VkSemaphore acquired = VK_NULL_HANDLE;
        std::shared_ptr<rhi::ITexture> source; // kept alive until `done` signals
    };

    void createSwapchain(uint32_t width, uint32_t height);
    void destroyImageSemaphores();
    void waitForPresents();
    void recordCopy(FrameSlot& slot, rhi::ITexture& image, uint32_t imageIndex);
    VkPresentModeKHR choosePresentMode() const;

    std::shared_ptr<Context> context_;
    uint32_t framesInFlight_ = 2;
    bool vsync_ = true;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE; // null while minimised
    VkSurfaceFormatKHR format_{};
    VkExtent2D extent_{0, 0};
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> imageReady_; // per image: signalled by the copy, waited by the present
    VkCommandPool pool_ = VK_NULL_HANDLE;
    std::vector<FrameSlot> slots_;
    uint64_t frame_ = 0;
};

} // namespace lumina::vulkan
