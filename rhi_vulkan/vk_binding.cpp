#include "rhi_vulkan/vk_binding.h"

#include "rhi/error.h"
#include "rhi/validation.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_descriptor_allocator.h"
#include "rhi_vulkan/vk_sampler.h"
#include "rhi_vulkan/vk_struct.h"
#include "rhi_vulkan/vk_texture.h"

#include <set>
#include <string>
#include <vector>

namespace lumina::vulkan {

namespace {

std::string registerName(rhi::BindingType type, uint32_t reg, uint32_t space) {
    return std::string(1, rhi::registerClass(type)) + std::to_string(reg) + ", space" + std::to_string(space);
}

bool isBufferBinding(rhi::BindingType type) {
    return type != rhi::BindingType::TextureSRV && type != rhi::BindingType::TextureUAV &&
           type != rhi::BindingType::Sampler;
}

VkDescriptorBufferInfo bufferInfo(const Context& context, const rhi::BindingSetItem& item,
                                  const std::string& where) {
    auto* buffer = dynamic_cast<Buffer*>(item.buffer.get());
    if (!buffer) {
        throw rhi::Error(where + ": no buffer bound");
    }
    const rhi::BufferDesc& desc = buffer->desc();
    const std::string what = where + " buffer '" + desc.debugName + "'";
    uint64_t size = 0;
    try {
        size = rhi::validateBufferBinding(item.type, *buffer, item.range);
    } catch (const rhi::Error& error) {
        throw rhi::Error(where + ": " + error.what());
    }
    // Beyond the RHI's rules (rhi/validation.h): this device's offset alignment and range.
    const bool constant = item.type == rhi::BindingType::ConstantBuffer;
    const VkPhysicalDeviceLimits& limits = context.limits();
    const uint64_t alignment =
        constant ? limits.minUniformBufferOffsetAlignment : limits.minStorageBufferOffsetAlignment;
    const uint64_t maxRange = constant ? limits.maxUniformBufferRange : limits.maxStorageBufferRange;
    if (item.range.offset % alignment != 0) {
        throw rhi::Error(what + ": range offset " + std::to_string(item.range.offset) +
                         " is not a multiple of this device's " + std::to_string(alignment));
    }
    if (size > maxRange) {
        if (!constant || item.range.size != 0) {
            throw rhi::Error(what + ": " + std::to_string(size) + " bytes bound, the device allows " +
                             std::to_string(maxRange));
        }
        size = maxRange; // a cbuffer declares what it reads: bind the first 64 KiB of a big buffer
    }
    return {buffer->handle(), item.range.offset, size};
}

VkDescriptorImageInfo textureInfo(const rhi::BindingSetItem& item, const std::string& where) {
    auto* texture = dynamic_cast<Texture*>(item.texture.get());
    if (!texture) {
        throw rhi::Error(where + ": no texture bound");
    }
    const bool storage = item.type == rhi::BindingType::TextureUAV;
    rhi::TextureSubresources sub = item.subresources;
    if (storage) {
        sub.mipCount = 1; // a UAV sees one mip
    }
    try {
        rhi::validateTextureBinding(item.type, *texture, sub);
    } catch (const rhi::Error& error) {
        throw rhi::Error(where + ": " + error.what());
    }
    VkDescriptorImageInfo info{};
    info.imageView = texture->view(bindingViewDimension(item), sub);
    info.imageLayout = storage ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    return info;
}

} // namespace

uint32_t bindingNumber(rhi::BindingType type, uint32_t reg) {
    switch (rhi::registerClass(type)) {
    case 'b':
        return kConstantBufferShift + reg;
    case 't':
        return kShaderResourceShift + reg;
    case 'u':
        return kUnorderedAccessShift + reg;
    default:
        return kSamplerShift + reg;
    }
}

VkDescriptorType descriptorType(rhi::BindingType type) {
    switch (type) {
    case rhi::BindingType::ConstantBuffer:
        return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case rhi::BindingType::TextureSRV:
        return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case rhi::BindingType::TextureUAV:
        return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    // Both compilers turn (RW)StructuredBuffer and (RW)ByteAddressBuffer into storage buffers.
    case rhi::BindingType::BufferSRV:
    case rhi::BindingType::RawBufferSRV:
    case rhi::BindingType::BufferUAV:
    case rhi::BindingType::RawBufferUAV:
        return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case rhi::BindingType::Sampler:
        return VK_DESCRIPTOR_TYPE_SAMPLER;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

VkShaderStageFlags shaderStages(rhi::ShaderStageMask mask) {
    const auto bits = static_cast<uint32_t>(mask);
    VkShaderStageFlags flags = 0;
    if (bits & static_cast<uint32_t>(rhi::ShaderStageMask::Compute)) {
        flags |= VK_SHADER_STAGE_COMPUTE_BIT;
    }
    if (bits & static_cast<uint32_t>(rhi::ShaderStageMask::Vertex)) {
        flags |= VK_SHADER_STAGE_VERTEX_BIT;
    }
    if (bits & static_cast<uint32_t>(rhi::ShaderStageMask::Pixel)) {
        flags |= VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    return flags;
}

rhi::TextureDimension bindingViewDimension(const rhi::BindingSetItem& item) {
    if (item.overrideDimension) {
        return item.viewDimension;
    }
    const rhi::TextureDimension own = item.texture->desc().dimension;
    const bool cube =
        own == rhi::TextureDimension::TextureCube || own == rhi::TextureDimension::TextureCubeArray;
    return item.type == rhi::BindingType::TextureUAV && cube ? rhi::TextureDimension::Texture2DArray : own;
}

BindingLayout::BindingLayout(std::shared_ptr<Context> context, const rhi::BindingLayoutDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    std::set<uint32_t> seen;
    for (const rhi::BindingLayoutItem& item : desc_.items) {
        if (item.reg >= kShaderResourceShift - kConstantBufferShift) {
            throw rhi::Error("createBindingLayout: register " +
                             registerName(item.type, item.reg, desc_.space) +
                             " is beyond the 100 registers per class that the binding shifts leave");
        }
        const uint32_t binding = bindingNumber(item.type, item.reg);
        if (!seen.insert(binding).second) {
            throw rhi::Error("createBindingLayout: register " +
                             registerName(item.type, item.reg, desc_.space) + " appears twice");
        }
        VkDescriptorSetLayoutBinding entry{};
        entry.binding = binding;
        entry.descriptorType = descriptorType(item.type);
        entry.descriptorCount = 1;
        entry.stageFlags = shaderStages(desc_.visibility);
        bindings.push_back(entry);
    }
    auto info =
        vkStruct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.bindingCount = static_cast<uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(context_->device(), &info, nullptr, &layout_),
          "vkCreateDescriptorSetLayout", "space" + std::to_string(desc_.space));
}

BindingLayout::~BindingLayout() {
    vkDestroyDescriptorSetLayout(context_->device(), layout_, nullptr);
}

VkDescriptorSet writeBindingSet(Context& context, DescriptorAllocator& allocator, const rhi::BindingSet& set,
                                std::string_view user) {
    const auto* layout = dynamic_cast<const BindingLayout*>(set.layout.get());
    if (!layout) {
        throw rhi::Error(std::string(user) + ": binding set without a Vulkan binding layout");
    }
    const rhi::BindingLayoutDesc& desc = layout->desc();
    if (set.items.size() != desc.items.size()) {
        throw rhi::Error(std::string(user) + " space" + std::to_string(desc.space) +
                         ": the binding set has " + std::to_string(set.items.size()) + " items, its layout " +
                         std::to_string(desc.items.size()));
    }
    const VkDescriptorSet descriptorSet = allocator.allocate(layout->handle(), user);

    // Reserved up front: the writes point into these arrays.
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<VkDescriptorImageInfo> images;
    buffers.reserve(desc.items.size());
    images.reserve(desc.items.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (const rhi::BindingLayoutItem& slot : desc.items) {
        const std::string where = std::string(user) + " " + registerName(slot.type, slot.reg, desc.space);
        const rhi::BindingSetItem* found = nullptr;
        for (const rhi::BindingSetItem& item : set.items) {
            if (item.reg == slot.reg && rhi::registerClass(item.type) == rhi::registerClass(slot.type)) {
                found = &item;
            }
        }
        if (!found) {
            throw rhi::Error(where + ": the layout declares it but the binding set has no item for it");
        }
        if (found->type != slot.type) {
            throw rhi::Error(where + ": the binding set's item is of another type than the layout's");
        }
        auto write = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        write.dstSet = descriptorSet;
        write.dstBinding = bindingNumber(slot.type, slot.reg);
        write.descriptorCount = 1;
        write.descriptorType = descriptorType(slot.type);
        if (isBufferBinding(slot.type)) {
            buffers.push_back(bufferInfo(context, *found, where));
            write.pBufferInfo = &buffers.back();
        } else if (slot.type == rhi::BindingType::Sampler) {
            const auto* sampler = dynamic_cast<const Sampler*>(found->sampler.get());
            if (!sampler) {
                throw rhi::Error(where + ": no sampler bound");
            }
            images.push_back({sampler->handle(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
            write.pImageInfo = &images.back();
        } else {
            images.push_back(textureInfo(*found, where));
            write.pImageInfo = &images.back();
        }
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(context.device(), static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
    return descriptorSet;
}

} // namespace lumina::vulkan
