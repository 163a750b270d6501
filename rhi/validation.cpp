// The backend-neutral rules of rhi/validation.h; the reason for each rule is there.
#include "rhi/validation.h"

#include "rhi/error.h"

#include <algorithm>
#include <bit>
#include <string>

namespace lumina::rhi {

namespace {

std::string sliceName(const ITexture& texture, TextureSlice slice) {
    return "texture '" + texture.debugName() + "' mip " + std::to_string(slice.mipLevel) + " layer " +
           std::to_string(slice.arrayLayer);
}

} // namespace

void validateBufferDesc(const BufferDesc& desc) {
    const std::string what = "createBuffer('" + desc.debugName + "')";
    if (desc.size == 0) {
        throw Error(what + ": size is 0");
    }
    if (hasFlag(desc.usage, BufferUsage::Structured) && desc.structStride == 0) {
        throw Error(what + ": Structured usage needs a structStride");
    }
    if (hasFlag(desc.usage, BufferUsage::Storage) && desc.memory != MemoryType::GpuOnly) {
        throw Error(what + ": Storage usage needs GpuOnly memory, not " + memoryTypeName(desc.memory) +
                    " (D3D12's upload and readback heaps take no UAVs)");
    }
}

void validateTextureDesc(const TextureDesc& desc) {
    const std::string what = "createTexture('" + desc.debugName + "', " +
                             textureDimensionName(desc.dimension) + " " +
                             std::string(formatInfo(desc.format).name) + ")";
    if (desc.format == Format::Unknown) {
        throw Error(what + ": format is Unknown");
    }
    if (desc.width == 0 || desc.height == 0 || desc.depth == 0 || desc.arrayLayers == 0 ||
        desc.mipLevels == 0) {
        throw Error(what + ": width, height, depth, arrayLayers and mipLevels must all be at least 1");
    }
    const bool is3D = desc.dimension == TextureDimension::Texture3D;
    if (!is3D && desc.depth != 1) {
        throw Error(what + ": depth must be 1 (use arrayLayers for layers)");
    }
    if (is3D && desc.arrayLayers != 1) {
        throw Error(what + ": a 3D texture has no array layers");
    }
    if (desc.dimension == TextureDimension::Texture2D && desc.arrayLayers != 1) {
        throw Error(what + ": a Texture2D has one layer; use Texture2DArray for " +
                    std::to_string(desc.arrayLayers));
    }
    const uint32_t largest = std::max({desc.width, desc.height, desc.depth});
    if (desc.mipLevels > uint32_t(std::bit_width(largest))) {
        throw Error(what + ": " + std::to_string(desc.mipLevels) + " mips, but a " + std::to_string(largest) +
                    "-texel texture has at most " + std::to_string(std::bit_width(largest)));
    }
    if (isCubeDimension(desc.dimension) && (desc.arrayLayers % 6 != 0 || desc.width != desc.height)) {
        throw Error(what + ": cube textures need square faces and 6 layers per cube, got " +
                    std::to_string(desc.width) + "x" + std::to_string(desc.height) + " with " +
                    std::to_string(desc.arrayLayers) + " layers");
    }
    if (desc.dimension == TextureDimension::TextureCube && desc.arrayLayers != 6) {
        throw Error(what + ": a TextureCube has exactly 6 layers (use TextureCubeArray)");
    }
    const bool depth = isDepthFormat(desc.format);
    if (depth &&
        (hasFlag(desc.usage, TextureUsage::Storage) || hasFlag(desc.usage, TextureUsage::RenderTarget))) {
        throw Error(what + ": depth formats cannot be storage or render-target textures");
    }
    if (hasFlag(desc.usage, TextureUsage::DepthStencil) && (!depth || is3D)) {
        throw Error(what + ": DepthStencil usage needs a 2D depth format");
    }
    if (hasFlag(desc.usage, TextureUsage::Storage) && desc.format == Format::RGBA8_SRGB) {
        throw Error(what + ": sRGB formats cannot be storage textures (D3D12 has no sRGB UAVs)");
    }
}

void validateSamplerDesc(const SamplerDesc& desc) {
    if (!(desc.maxAnisotropy >= 1.0f && desc.maxAnisotropy <= kMaxSamplerAnisotropy)) {
        throw Error("createSampler('" + desc.debugName + "'): maxAnisotropy " +
                    std::to_string(desc.maxAnisotropy) + " is outside [1, " +
                    std::to_string(int(kMaxSamplerAnisotropy)) + "]");
    }
}

uint64_t validateBufferBinding(BindingType type, const IBuffer& buffer, BufferRange range) {
    const BufferDesc& desc = buffer.desc();
    const std::string what = "buffer '" + desc.debugName + "' bound as " + bindingTypeName(type);
    if (desc.memory == MemoryType::Readback) {
        throw Error(what +
                    ": Readback buffers are copy destinations only (D3D12 readback heaps take no views)");
    }
    const uint64_t size = range.offset < desc.size && range.size == 0 ? desc.size - range.offset : range.size;
    if (range.offset >= desc.size || size == 0 || size > desc.size - range.offset) {
        throw Error(what + ": range " + std::to_string(range.offset) + "+" + std::to_string(size) +
                    " is empty or outside its " + std::to_string(desc.size) + " bytes");
    }
    if (isWriteBinding(type) && !hasFlag(desc.usage, BufferUsage::Storage)) {
        throw Error(what + ": bound read-write (u register) without BufferUsage::Storage");
    }
    uint64_t alignment = 0;
    switch (type) {
    case BindingType::ConstantBuffer:
        if (!hasFlag(desc.usage, BufferUsage::Constant)) {
            throw Error(what + ": the buffer lacks BufferUsage::Constant");
        }
        alignment = kConstantBufferOffsetAlignment;
        break;
    case BindingType::BufferSRV:
    case BindingType::BufferUAV:
        if (!hasFlag(desc.usage, BufferUsage::Structured) || desc.structStride == 0) {
            throw Error(what + ": the buffer lacks BufferUsage::Structured and a structStride");
        }
        alignment = desc.structStride;
        break;
    case BindingType::RawBufferSRV:
    case BindingType::RawBufferUAV:
        if (!hasFlag(desc.usage, BufferUsage::Raw)) {
            throw Error(what + ": the buffer lacks BufferUsage::Raw");
        }
        alignment = kRawBufferOffsetAlignment;
        break;
    case BindingType::TextureSRV:
    case BindingType::TextureUAV:
    case BindingType::Sampler:
        throw Error(what + ": not a buffer binding");
    }
    if (range.offset % alignment != 0) {
        throw Error(what + ": offset " + std::to_string(range.offset) + " is not a multiple of " +
                    std::to_string(alignment));
    }
    return size;
}

void validateTextureBinding(BindingType type, const ITexture& texture, const TextureSubresources& sub) {
    const TextureDesc& desc = texture.desc();
    const std::string what = "texture '" + desc.debugName + "' bound as " + bindingTypeName(type);
    const TextureUsage usage =
        type == BindingType::TextureUAV ? TextureUsage::Storage : TextureUsage::Sampled;
    if (type != BindingType::TextureSRV && type != BindingType::TextureUAV) {
        throw Error(what + ": not a texture binding");
    }
    if (!hasFlag(desc.usage, usage)) {
        throw Error(what + ": the texture lacks TextureUsage::" +
                    (usage == TextureUsage::Storage ? "Storage" : "Sampled"));
    }
    const uint32_t layers = sliceLayerCount(desc);
    const uint32_t mips =
        sub.mipCount ? sub.mipCount : desc.mipLevels - std::min(sub.baseMip, desc.mipLevels);
    const uint32_t count = sub.layerCount ? sub.layerCount : layers - std::min(sub.baseLayer, layers);
    if (mips == 0 || sub.baseMip + mips > desc.mipLevels || count == 0 || sub.baseLayer + count > layers) {
        throw Error(what + ": mips " + std::to_string(sub.baseMip) + "+" + std::to_string(mips) +
                    ", layers " + std::to_string(sub.baseLayer) + "+" + std::to_string(count) +
                    " lie outside its " + std::to_string(desc.mipLevels) + " mips and " +
                    std::to_string(layers) + " layers");
    }
}

void validateBufferRange(const char* command, const IBuffer& buffer, uint64_t offset, uint64_t size) {
    const uint64_t bufferSize = buffer.desc().size;
    if (offset > bufferSize || size > bufferSize - offset) {
        throw Error(std::string(command) + ": bytes " + std::to_string(offset) + "+" + std::to_string(size) +
                    " are outside buffer '" + buffer.debugName() + "' (" + std::to_string(bufferSize) +
                    " bytes)");
    }
}

void validateTextureSlice(const char* command, const ITexture& texture, TextureSlice slice) {
    const TextureDesc& desc = texture.desc();
    const uint32_t layers = sliceLayerCount(desc);
    if (slice.mipLevel >= desc.mipLevels || slice.arrayLayer >= layers) {
        throw Error(std::string(command) + ": " + sliceName(texture, slice) + " does not exist (" +
                    std::to_string(desc.mipLevels) + " mips, " + std::to_string(layers) + " layers)");
    }
}

void validateBufferTextureCopy(const char* command, const ITexture& texture, TextureSlice slice,
                               const IBuffer& buffer, uint64_t offset, uint32_t rowPitch) {
    validateTextureSlice(command, texture, slice);
    const Extent3D extent = mipExtent(texture.desc(), slice.mipLevel);
    const uint64_t packedRow = uint64_t(extent.width) * formatInfo(texture.desc().format).bytesPerTexel;
    const std::string what =
        std::string(command) + ": " + sliceName(texture, slice) + ", buffer '" + buffer.debugName() + "'";
    if (rowPitch % kTextureCopyRowAlignment != 0 || rowPitch < packedRow) {
        throw Error(what + ": row pitch " + std::to_string(rowPitch) + " must be a multiple of " +
                    std::to_string(kTextureCopyRowAlignment) + " and at least " + std::to_string(packedRow));
    }
    if (offset % kTextureCopyOffsetAlignment != 0) {
        throw Error(what + ": buffer offset " + std::to_string(offset) + " must be a multiple of " +
                    std::to_string(kTextureCopyOffsetAlignment));
    }
    const uint64_t rows = uint64_t(extent.height) * extent.depth;
    if (offset + rowPitch * rows > buffer.desc().size) {
        throw Error(what + ": " + std::to_string(rows) + " rows of " + std::to_string(rowPitch) +
                    " bytes at offset " + std::to_string(offset) + " do not fit in its " +
                    std::to_string(buffer.desc().size) + " bytes");
    }
}

void validateTextureCopy(const ITexture& dst, TextureSlice dstSlice, const ITexture& src,
                         TextureSlice srcSlice) {
    validateTextureSlice("copyTexture (destination)", dst, dstSlice);
    validateTextureSlice("copyTexture (source)", src, srcSlice);
    const Extent3D to = mipExtent(dst.desc(), dstSlice.mipLevel);
    const Extent3D from = mipExtent(src.desc(), srcSlice.mipLevel);
    const std::string what = "copyTexture: " + sliceName(src, srcSlice) + " -> " + sliceName(dst, dstSlice);
    if (to.width != from.width || to.height != from.height || to.depth != from.depth) {
        throw Error(what + ": extents differ (" + std::to_string(from.width) + "x" +
                    std::to_string(from.height) + "x" + std::to_string(from.depth) + " -> " +
                    std::to_string(to.width) + "x" + std::to_string(to.height) + "x" +
                    std::to_string(to.depth) + ")");
    }
    if (dst.desc().format != src.desc().format) {
        throw Error(what + ": formats differ (" + std::string(formatInfo(src.desc().format).name) + " -> " +
                    std::string(formatInfo(dst.desc().format).name) + ")");
    }
}

} // namespace lumina::rhi
