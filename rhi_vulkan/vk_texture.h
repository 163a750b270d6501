#pragma once
#include "rhi/binding.h"
#include "rhi/resource.h"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

// A VkImage with its own memory, and the image views commands ask for, created on first
// use per (view type, mip range, layer range) and kept until the texture dies.
class Texture final : public rhi::ITexture, public std::enable_shared_from_this<Texture> {
public:
    Texture(std::shared_ptr<Context> context, const rhi::TextureDesc& desc);
    ~Texture() override;
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    const rhi::TextureDesc& desc() const override { return desc_; }

    VkImage handle() const { return image_; }
    VkFormat format() const { return format_; }
    VkImageAspectFlags aspect() const;
    // Array layers of the VkImage (1 for a 3D texture).
    uint32_t layerCount() const;
    VkImageSubresourceRange fullRange() const;
    VkExtent3D mipExtent(uint32_t mip) const;

    // A view of `dimension` over `sub` (zero counts: everything from the base). Throws with
    // the texture's name when the range or dimension does not fit the texture.
    VkImageView view(rhi::TextureDimension dimension, const rhi::TextureSubresources& sub);
    // A single-layer 2D view of one mip, for a render or depth attachment.
    VkImageView attachmentView(uint32_t mip, uint32_t layer);

private:
    std::shared_ptr<Context> context_;
    rhi::TextureDesc desc_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memorySize_ = 0;

    using ViewKey = std::tuple<VkImageViewType, uint32_t, uint32_t, uint32_t, uint32_t>;
    std::mutex viewMutex_; // views may be asked for by command lists on several threads
    std::map<ViewKey, VkImageView> views_;
};

} // namespace lumina::vulkan
