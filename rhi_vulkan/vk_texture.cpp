#include "rhi_vulkan/vk_texture.h"

#include "rhi/error.h"
#include "rhi/validation.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_format.h"
#include "rhi_vulkan/vk_struct.h"

#include <algorithm>
#include <string>

namespace lumina::vulkan {

namespace {

VkImageUsageFlags usageFlags(rhi::TextureUsage usage) {
    using U = rhi::TextureUsage;
    // Uploads, readbacks and clears are transfers: every texture allows them.
    VkImageUsageFlags flags = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (hasFlag(usage, U::Sampled)) {
        flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
    }
    if (hasFlag(usage, U::Storage)) {
        flags |= VK_IMAGE_USAGE_STORAGE_BIT;
    }
    if (hasFlag(usage, U::RenderTarget)) {
        flags |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    }
    if (hasFlag(usage, U::DepthStencil)) {
        flags |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    }
    return flags;
}

VkImageViewType viewType(rhi::TextureDimension dimension) {
    switch (dimension) {
    case rhi::TextureDimension::Texture2D:
        return VK_IMAGE_VIEW_TYPE_2D;
    case rhi::TextureDimension::Texture2DArray:
        return VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    case rhi::TextureDimension::Texture3D:
        return VK_IMAGE_VIEW_TYPE_3D;
    case rhi::TextureDimension::TextureCube:
        return VK_IMAGE_VIEW_TYPE_CUBE;
    case rhi::TextureDimension::TextureCubeArray:
        return VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
    }
    return VK_IMAGE_VIEW_TYPE_2D;
}

} // namespace

Texture::Texture(std::shared_ptr<Context> context, const rhi::TextureDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateTextureDesc(desc_);
    format_ = toVkFormat(desc_.format);
    const VkDevice device = context_->device();

    auto info = vkStruct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.flags = rhi::isCubeDimension(desc_.dimension) ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType =
        desc_.dimension == rhi::TextureDimension::Texture3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = format_;
    info.extent = {desc_.width, desc_.height, desc_.depth};
    info.mipLevels = desc_.mipLevels;
    info.arrayLayers = desc_.arrayLayers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usageFlags(desc_.usage);
    const auto& families = context_->queueFamilies();
    info.sharingMode = families.size() > 1 ? VK_SHARING_MODE_CONCURRENT : VK_SHARING_MODE_EXCLUSIVE;
    info.queueFamilyIndexCount = families.size() > 1 ? static_cast<uint32_t>(families.size()) : 0;
    info.pQueueFamilyIndices = families.data();
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;

    VkImageFormatProperties limits{};
    const VkResult supported =
        vkGetPhysicalDeviceImageFormatProperties(context_->physicalDevice(), info.format, info.imageType,
                                                 info.tiling, info.usage, info.flags, &limits);
    const std::string name =
        "'" + desc_.debugName + "' (" + std::string(rhi::formatInfo(desc_.format).name) + ")";
    if (supported == VK_ERROR_FORMAT_NOT_SUPPORTED) {
        throw rhi::Error("createTexture " + name + ": " + context_->adapter().name +
                         " does not support this format with this dimension and usage");
    }
    check(supported, "vkGetPhysicalDeviceImageFormatProperties", name);
    if (desc_.width > limits.maxExtent.width || desc_.height > limits.maxExtent.height ||
        desc_.depth > limits.maxExtent.depth || desc_.arrayLayers > limits.maxArrayLayers) {
        throw rhi::Error("createTexture " + name + ": larger than the device allows (" +
                         std::to_string(limits.maxExtent.width) + "x" +
                         std::to_string(limits.maxExtent.height) + "x" +
                         std::to_string(limits.maxExtent.depth) + ", " +
                         std::to_string(limits.maxArrayLayers) + " layers)");
    }

    check(vkCreateImage(device, &info, nullptr, &image_), "vkCreateImage", name);
    context_->setName(VK_OBJECT_TYPE_IMAGE, image_, desc_.debugName);
    try {
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device, image_, &requirements);
        memory_ = context_->allocateMemory(requirements, rhi::MemoryType::GpuOnly, desc_.debugName);
        memorySize_ = requirements.size;
        check(vkBindImageMemory(device, image_, memory_, 0), "vkBindImageMemory", name);
    } catch (...) {
        context_->freeMemory(memory_, memorySize_);
        vkDestroyImage(device, image_, nullptr);
        throw;
    }
}

Texture::~Texture() {
    const VkDevice device = context_->device();
    for (const auto& [key, view] : views_) {
        vkDestroyImageView(device, view, nullptr);
    }
    vkDestroyImage(device, image_, nullptr);
    context_->freeMemory(memory_, memorySize_);
}

VkImageAspectFlags Texture::aspect() const {
    return aspectMask(desc_.format);
}

uint32_t Texture::layerCount() const {
    return rhi::sliceLayerCount(desc_);
}

VkImageSubresourceRange Texture::fullRange() const {
    return {aspect(), 0, desc_.mipLevels, 0, layerCount()};
}

VkExtent3D Texture::mipExtent(uint32_t mip) const {
    const rhi::Extent3D extent = rhi::mipExtent(desc_, mip);
    return {extent.width, extent.height, extent.depth};
}

VkImageView Texture::view(rhi::TextureDimension dimension, const rhi::TextureSubresources& sub) {
    const uint32_t layers = layerCount();
    const uint32_t mipCount =
        sub.mipCount ? sub.mipCount : desc_.mipLevels - std::min(sub.baseMip, desc_.mipLevels);
    const uint32_t layerCount = sub.layerCount ? sub.layerCount : layers - std::min(sub.baseLayer, layers);
    const std::string where = "view of texture '" + desc_.debugName + "' as " +
                              rhi::textureDimensionName(dimension) + " (mips " + std::to_string(sub.baseMip) +
                              "+" + std::to_string(mipCount) + ", layers " + std::to_string(sub.baseLayer) +
                              "+" + std::to_string(layerCount) + ")";
    if (mipCount == 0 || sub.baseMip + mipCount > desc_.mipLevels || layerCount == 0 ||
        sub.baseLayer + layerCount > layers) {
        throw rhi::Error(where + ": outside the texture's " + std::to_string(desc_.mipLevels) + " mips and " +
                         std::to_string(layers) + " layers");
    }
    const bool is3D = desc_.dimension == rhi::TextureDimension::Texture3D;
    if (is3D != (dimension == rhi::TextureDimension::Texture3D)) {
        throw rhi::Error(where + ": 3D textures have only 3D views, and 3D views need a 3D texture");
    }
    if (dimension == rhi::TextureDimension::Texture2D && layerCount != 1) {
        throw rhi::Error(where + ": a Texture2D view has exactly one layer");
    }
    if (rhi::isCubeDimension(dimension) &&
        (!rhi::isCubeDimension(desc_.dimension) || layerCount % 6 != 0 ||
         (dimension == rhi::TextureDimension::TextureCube && layerCount != 6))) {
        throw rhi::Error(where + ": cube views need a cube texture and 6 layers per cube");
    }
    if (dimension == rhi::TextureDimension::TextureCubeArray && !context_->features().imageCubeArray) {
        throw rhi::Error(where + ": the device does not support cube-array views (imageCubeArray)");
    }

    const ViewKey key{viewType(dimension), sub.baseMip, mipCount, sub.baseLayer, layerCount};
    std::lock_guard lock(viewMutex_);
    if (const auto it = views_.find(key); it != views_.end()) {
        return it->second;
    }
    auto info = vkStruct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    info.image = image_;
    info.viewType = viewType(dimension);
    info.format = format_;
    info.subresourceRange = {aspect(), sub.baseMip, mipCount, sub.baseLayer, layerCount};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(context_->device(), &info, nullptr, &view), "vkCreateImageView", where);
    context_->setName(VK_OBJECT_TYPE_IMAGE_VIEW, view, desc_.debugName);
    views_.emplace(key, view);
    return view;
}

VkImageView Texture::attachmentView(uint32_t mip, uint32_t layer) {
    if (desc_.dimension == rhi::TextureDimension::Texture3D) {
        throw rhi::Error("texture '" + desc_.debugName + "' is 3D; 3D textures cannot be attachments");
    }
    return view(rhi::TextureDimension::Texture2D,
                {.baseMip = mip, .mipCount = 1, .baseLayer = layer, .layerCount = 1});
}

} // namespace lumina::vulkan
