#include "rhi/binding.h"

#include <utility>

namespace lumina::rhi {

namespace {
BindingSetItem bufferItem(BindingType type, uint32_t reg, BufferHandle buffer, BufferRange range) {
    BindingSetItem item;
    item.type = type;
    item.reg = reg;
    item.buffer = std::move(buffer);
    item.range = range;
    return item;
}
} // namespace

BindingSetItem BindingSetItem::constantBuffer(uint32_t reg, BufferHandle buffer, BufferRange range) {
    return bufferItem(BindingType::ConstantBuffer, reg, std::move(buffer), range);
}
BindingSetItem BindingSetItem::structuredBuffer(uint32_t reg, BufferHandle buffer, BufferRange range) {
    return bufferItem(BindingType::BufferSRV, reg, std::move(buffer), range);
}
BindingSetItem BindingSetItem::rwStructuredBuffer(uint32_t reg, BufferHandle buffer, BufferRange range) {
    return bufferItem(BindingType::BufferUAV, reg, std::move(buffer), range);
}
BindingSetItem BindingSetItem::rawBuffer(uint32_t reg, BufferHandle buffer, BufferRange range) {
    return bufferItem(BindingType::RawBufferSRV, reg, std::move(buffer), range);
}
BindingSetItem BindingSetItem::rwRawBuffer(uint32_t reg, BufferHandle buffer, BufferRange range) {
    return bufferItem(BindingType::RawBufferUAV, reg, std::move(buffer), range);
}

BindingSetItem BindingSetItem::sampledTexture(uint32_t reg, TextureHandle texture, TextureSubresources sub) {
    BindingSetItem item;
    item.type = BindingType::TextureSRV;
    item.reg = reg;
    item.texture = std::move(texture);
    item.subresources = sub;
    return item;
}

BindingSetItem BindingSetItem::storageTexture(uint32_t reg, TextureHandle texture, uint32_t mip) {
    BindingSetItem item;
    item.type = BindingType::TextureUAV;
    item.reg = reg;
    item.texture = std::move(texture);
    item.subresources.baseMip = mip;
    item.subresources.mipCount = 1;
    return item;
}

BindingSetItem BindingSetItem::samplerState(uint32_t reg, SamplerHandle sampler) {
    BindingSetItem item;
    item.type = BindingType::Sampler;
    item.reg = reg;
    item.sampler = std::move(sampler);
    return item;
}

ResourceState requiredState(BindingType type) {
    switch (type) {
    case BindingType::ConstantBuffer:
        return ResourceState::ConstantBuffer;
    case BindingType::TextureSRV:
    case BindingType::BufferSRV:
    case BindingType::RawBufferSRV:
        return ResourceState::ShaderResource;
    case BindingType::TextureUAV:
    case BindingType::BufferUAV:
    case BindingType::RawBufferUAV:
        return ResourceState::UnorderedAccess;
    case BindingType::Sampler:
        break;
    }
    return ResourceState::Undefined;
}

bool isWriteBinding(BindingType type) { return requiredState(type) == ResourceState::UnorderedAccess; }

} // namespace lumina::rhi
