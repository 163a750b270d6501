#include "rhi_vulkan/vk_swapchain.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"
#include "rhi_vulkan/vk_swapchain_surface.h"
#include "rhi_vulkan/vk_texture.h"

#include <algorithm>
#include <limits>
#include <string>

namespace lumina::vulkan {

namespace {

constexpr uint64_t kNoTimeout = std::numeric_limits<uint64_t>::max();

// The frame is display-encoded already (the composite applies the sRGB OETF), so the surface
// format must be UNORM: an _SRGB image would encode it twice. RGBA8 is a plain copy; BGRA8,
// what most surfaces offer, is a blit that swizzles.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    for (VkFormat wanted : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM}) {
        for (const VkSurfaceFormatKHR& format : formats) {
            if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
                return format;
            }
        }
    }
    throw rhi::Error("Vulkan swapchain: the surface offers neither R8G8B8A8_UNORM nor B8G8R8A8_UNORM (" +
                     std::to_string(count) + " formats)");
}

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageLayout before, VkImageLayout after,
                                   VkAccessFlags2 srcAccess, VkAccessFlags2 dstAccess) {
    auto barrier = vkStruct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    // Transfer on both sides: the acquire semaphore's wait names the transfer stage, so the
    // layout transition out of UNDEFINED is chained after it.
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstAccess ? VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT : VK_PIPELINE_STAGE_2_NONE;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = before;
    barrier.newLayout = after;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    return barrier;
}

} // namespace

Swapchain::Swapchain(std::shared_ptr<Context> context, const rhi::SwapchainDesc& desc)
    : context_(std::move(context)), framesInFlight_(std::clamp(desc.framesInFlight, 2u, 3u)),
      vsync_(desc.vsync) {
    if (!context_->features().swapchain) {
        throw rhi::Error("createSwapchain: the device was created without DeviceDesc::presentation");
    }
    surface_ = createSurface(context_->instance(), desc.window);
    const HardwareQueue& queue = *context_->graphicsQueue();
    VkBool32 supported = VK_FALSE;
    check(
        vkGetPhysicalDeviceSurfaceSupportKHR(context_->physicalDevice(), queue.family, surface_, &supported),
        "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) {
        vkDestroySurfaceKHR(context_->instance(), surface_, nullptr);
        throw rhi::Error("Vulkan swapchain: adapter '" + context_->adapter().name +
                         "' cannot present from its graphics queue to this window");
    }
    format_ = chooseFormat(context_->physicalDevice(), surface_);

    const VkDevice device = context_->device();
    auto poolInfo = vkStruct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queue.family;
    check(vkCreateCommandPool(device, &poolInfo, nullptr, &pool_), "vkCreateCommandPool", "swapchain");
    slots_.resize(framesInFlight_);
    for (FrameSlot& slot : slots_) {
        auto allocate = vkStruct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        allocate.commandPool = pool_;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device, &allocate, &slot.commands), "vkAllocateCommandBuffers",
              "swapchain");
        auto fence = vkStruct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        check(vkCreateFence(device, &fence, nullptr, &slot.done), "vkCreateFence", "swapchain");
        auto semaphore = vkStruct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        check(vkCreateSemaphore(device, &semaphore, nullptr, &slot.acquired), "vkCreateSemaphore",
              "swapchain");
        context_->setName(VK_OBJECT_TYPE_COMMAND_BUFFER, slot.commands, "swapchain copy");
    }
    createSwapchain(desc.width, desc.height);
}

Swapchain::~Swapchain() {
    try {
        waitForPresents();
    } catch (const rhi::Error&) {
        // Device lost: nothing left to wait for, and destructors must not throw.
    }
    const VkDevice device = context_->device();
    destroyImageSemaphores();
    if (swapchain_) {
        vkDestroySwapchainKHR(device, swapchain_, nullptr);
    }
    for (FrameSlot& slot : slots_) {
        vkDestroyFence(device, slot.done, nullptr);
        vkDestroySemaphore(device, slot.acquired, nullptr);
    }
    vkDestroyCommandPool(device, pool_, nullptr);
    vkDestroySurfaceKHR(context_->instance(), surface_, nullptr);
}

VkPresentModeKHR Swapchain::choosePresentMode() const {
    if (vsync_) {
        return VK_PRESENT_MODE_FIFO_KHR; // always supported
    }
    uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfacePresentModesKHR(context_->physicalDevice(), surface_, &count, nullptr),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
    std::vector<VkPresentModeKHR> modes(count);
    check(
        vkGetPhysicalDeviceSurfacePresentModesKHR(context_->physicalDevice(), surface_, &count, modes.data()),
        "vkGetPhysicalDeviceSurfacePresentModesKHR");
    // Mailbox never tears; immediate may, but is what most drivers without mailbox offer.
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) {
            return wanted;
        }
    }
    return VK_PRESENT_MODE_FIFO_KHR;
}

void Swapchain::waitForPresents() {
    std::vector<VkFence> fences;
    for (const FrameSlot& slot : slots_) {
        fences.push_back(slot.done);
    }
    if (!fences.empty()) {
        check(
            vkWaitForFences(context_->device(), uint32_t(fences.size()), fences.data(), VK_TRUE, kNoTimeout),
            "vkWaitForFences", "swapchain");
    }
    // The presentation engine's reads of the images and its semaphore waits are not covered
    // by the fences; a queue idle is (presents are queue operations).
    HardwareQueue& queue = *context_->graphicsQueue();
    std::lock_guard lock(queue.submitMutex);
    check(vkQueueWaitIdle(queue.queue), "vkQueueWaitIdle", "swapchain");
}

void Swapchain::destroyImageSemaphores() {
    for (VkSemaphore semaphore : imageReady_) {
        vkDestroySemaphore(context_->device(), semaphore, nullptr);
    }
    imageReady_.clear();
}

void Swapchain::createSwapchain(uint32_t width, uint32_t height) {
    const VkDevice device = context_->device();
    VkSurfaceCapabilitiesKHR caps{};
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_->physicalDevice(), surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == std::numeric_limits<uint32_t>::max()) { // the surface takes the swapchain's size
        extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    VkSwapchainKHR old = swapchain_;
    destroyImageSemaphores();
    images_.clear();
    if (extent.width == 0 || extent.height == 0 || width == 0 || height == 0) {
        // Minimised: no swapchain can exist at zero size; presents are skipped until resize().
        if (old) {
            vkDestroySwapchainKHR(device, old, nullptr);
        }
        swapchain_ = VK_NULL_HANDLE;
        extent_ = {0, 0};
        return;
    }
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
        throw rhi::Error(
            "Vulkan swapchain: the surface's images cannot be copied to (no TRANSFER_DST usage)");
    }

    auto info = vkStruct<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
    info.surface = surface_;
    // One image more than the frames in flight, so an acquire rarely waits on the display.
    info.minImageCount = std::max(caps.minImageCount, framesInFlight_ + 1);
    if (caps.maxImageCount != 0) {
        info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    }
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    info.presentMode = choosePresentMode();
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    check(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR",
          std::to_string(extent.width) + "x" + std::to_string(extent.height));
    if (old) {
        vkDestroySwapchainKHR(device, old, nullptr);
    }
    extent_ = extent;

    uint32_t count = 0;
    check(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr), "vkGetSwapchainImagesKHR");
    images_.resize(count);
    check(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()), "vkGetSwapchainImagesKHR");
    imageReady_.resize(count);
    for (VkSemaphore& semaphore : imageReady_) {
        auto semaphoreInfo = vkStruct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        check(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &semaphore), "vkCreateSemaphore",
              "swapchain");
    }
}

void Swapchain::resize(uint32_t width, uint32_t height, bool vsync) {
    waitForPresents();
    vsync_ = vsync;
    createSwapchain(width, height);
}

void Swapchain::recordCopy(FrameSlot& slot, rhi::ITexture& image, uint32_t imageIndex) {
    auto* source = dynamic_cast<Texture*>(&image);
    if (!source) {
        throw rhi::Error("present: texture '" + image.debugName() + "' is not a Vulkan texture");
    }
    slot.source = source->shared_from_this();
    const VkImage target = images_[imageIndex];

    auto begin = vkStruct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(slot.commands, &begin), "vkBeginCommandBuffer", "swapchain");
    VkImageMemoryBarrier2 toCopy =
        imageBarrier(target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_ACCESS_2_NONE, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    auto dependency = vkStruct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &toCopy;
    vkCmdPipelineBarrier2(slot.commands, &dependency);

    const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    if (format_.format == source->format()) {
        VkImageCopy region{};
        region.srcSubresource = layers;
        region.dstSubresource = layers;
        region.extent = {extent_.width, extent_.height, 1};
        vkCmdCopyImage(slot.commands, source->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    } else {
        VkImageBlit region{};
        region.srcSubresource = layers;
        region.dstSubresource = layers;
        region.srcOffsets[1] = {int32_t(extent_.width), int32_t(extent_.height), 1};
        region.dstOffsets[1] = region.srcOffsets[1];
        vkCmdBlitImage(slot.commands, source->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    }

    VkImageMemoryBarrier2 toPresent =
        imageBarrier(target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_ACCESS_2_NONE);
    dependency.pImageMemoryBarriers = &toPresent;
    vkCmdPipelineBarrier2(slot.commands, &dependency);
    check(vkEndCommandBuffer(slot.commands), "vkEndCommandBuffer", "swapchain");
}

rhi::PresentResult Swapchain::present(rhi::ITexture& image) {
    if (!swapchain_) {
        return rhi::PresentResult::Skipped;
    }
    const rhi::TextureDesc& desc = image.desc();
    if (desc.format != rhi::Format::RGBA8_UNORM || desc.width != extent_.width ||
        desc.height != extent_.height) {
        throw rhi::Error("present: texture '" + image.debugName() + "' must be RGBA8_UNORM " +
                         std::to_string(extent_.width) + "x" + std::to_string(extent_.height) +
                         ", the swapchain's size");
    }
    if (image.trackedState != rhi::ResourceState::CopySource) {
        throw rhi::Error("present: texture '" + image.debugName() +
                         "' must be transitioned to CopySource by the last command list submitted");
    }
    const VkDevice device = context_->device();
    FrameSlot& slot = slots_[frame_ % slots_.size()];
    check(vkWaitForFences(device, 1, &slot.done, VK_TRUE, kNoTimeout), "vkWaitForFences", "swapchain");
    slot.source.reset();

    uint32_t imageIndex = 0;
    const VkResult acquired =
        vkAcquireNextImageKHR(device, swapchain_, kNoTimeout, slot.acquired, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        resize(extent_.width, extent_.height, vsync_);
        return rhi::PresentResult::Skipped;
    }
    check(acquired, "vkAcquireNextImageKHR");
    check(vkResetFences(device, 1, &slot.done), "vkResetFences", "swapchain");
    recordCopy(slot, image, imageIndex);

    auto wait = vkStruct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    wait.semaphore = slot.acquired;
    wait.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    auto signal = vkStruct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    signal.semaphore = imageReady_[imageIndex];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    auto commands = vkStruct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    commands.commandBuffer = slot.commands;
    auto submit = vkStruct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submit.waitSemaphoreInfoCount = 1;
    submit.pWaitSemaphoreInfos = &wait;
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &commands;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;

    auto presentInfo = vkStruct<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &imageReady_[imageIndex];
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &swapchain_;
    presentInfo.pImageIndices = &imageIndex;
    VkResult presented = VK_SUCCESS;
    {
        // Submitted on the graphics queue after every command list already submitted there,
        // which is what orders the copy after the frame that wrote `image`.
        HardwareQueue& queue = *context_->graphicsQueue();
        std::lock_guard lock(queue.submitMutex);
        check(vkQueueSubmit2(queue.queue, 1, &submit, slot.done), "vkQueueSubmit2", "swapchain copy");
        presented = vkQueuePresentKHR(queue.queue, &presentInfo);
    }
    ++frame_;
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        acquired == VK_SUBOPTIMAL_KHR) {
        return rhi::PresentResult::Suboptimal;
    }
    check(presented, "vkQueuePresentKHR");
    return rhi::PresentResult::Presented;
}

} // namespace lumina::vulkan
