// Copies, uploads, fills and clears of d3d12::CommandList.
#include "rhi/validation.h"
#include "rhi_d3d12/d3d12_buffer.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_command_list.h"
#include "rhi_d3d12/d3d12_texture.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace lumina::d3d12 {

namespace {

static_assert(rhi::kTextureCopyOffsetAlignment == D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT);
static_assert(rhi::kTextureCopyRowAlignment == D3D12_TEXTURE_DATA_PITCH_ALIGNMENT);
constexpr uint64_t kBufferCopyAlignment = 16;
// fillBuffer clears a buffer up to this size with ClearUnorderedAccessViewUint, a larger one by
// copies. vkd3d 1.6 (Wine's D3D12) runs that clear as one dispatch of 32-thread groups, one word
// per thread, and Vulkan allows 65535 groups: 8 MiB. Beyond it the validation layer beneath vkd3d
// reported the dispatch (the voxel lighting's 24 MiB accumulator), and a driver may clear only
// part of the buffer. Views of 8 MiB pieces of the buffer did not help: vkd3d dispatched for the
// whole resource.
constexpr uint64_t kLargestUavClearBytes = 65535ull * 32 * 4;
// The upload memory a copy-based fill takes: the pattern once, copied as often as it takes.
constexpr uint64_t kFillChunkBytes = 1ull << 20;
// Render-target clears of UINT formats pass floats; integers above 2^24 would round.
constexpr uint32_t kExactFloatIntegers = 1u << 24;

// IEEE binary16, round to nearest even; overflow becomes infinity.
uint16_t toHalf(float value) {
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    const uint32_t sign = (bits >> 16) & 0x8000u;
    const uint32_t magnitude = bits & 0x7FFFFFFFu;
    if (magnitude >= 0x7F800000u) { // Inf or NaN
        return uint16_t(sign | 0x7C00u | (magnitude > 0x7F800000u ? 0x200u : 0u));
    }
    if (magnitude >= 0x477FF000u) { // rounds to beyond the largest half
        return uint16_t(sign | 0x7C00u);
    }
    if (magnitude < 0x38800000u) { // subnormal half (or zero)
        const float scaled =
            std::bit_cast<float>(magnitude) * 16777216.0f; // 2^24: units of the smallest subnormal
        return uint16_t(sign | uint32_t(std::nearbyint(scaled)));
    }
    const uint32_t rounded = magnitude + 0xFFFu + ((magnitude >> 13) & 1u) - 0x38000000u;
    return uint16_t(sign | (rounded >> 13));
}

uint8_t toUnorm8(float value) {
    return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

float linearToSrgb(float value) {
    value = std::clamp(value, 0.0f, 1.0f);
    return value <= 0.0031308f ? value * 12.92f : 1.055f * std::pow(value, 1.0f / 2.4f) - 0.055f;
}

// One texel of `format` holding the clear value, as the GPU's own clear would write it.
std::array<uint8_t, 16> encodeTexel(rhi::Format format, const std::array<float, 4>& value,
                                    const std::array<uint32_t, 4>& uintValue) {
    std::array<uint8_t, 16> texel{};
    const rhi::FormatInfo& info = rhi::formatInfo(format);
    for (uint32_t c = 0; c < info.channels; ++c) {
        switch (format) {
        case rhi::Format::R8_UNORM:
        case rhi::Format::RGBA8_UNORM:
            texel[c] = toUnorm8(value[c]);
            break;
        case rhi::Format::RGBA8_SRGB:
            texel[c] = toUnorm8(c < 3 ? linearToSrgb(value[c]) : value[c]);
            break;
        case rhi::Format::R16_FLOAT:
        case rhi::Format::RG16_FLOAT:
        case rhi::Format::RGBA16_FLOAT: {
            const uint16_t half = toHalf(value[c]);
            std::memcpy(texel.data() + c * 2, &half, 2);
            break;
        }
        case rhi::Format::R32_UINT:
        case rhi::Format::RG32_UINT:
        case rhi::Format::RGBA32_UINT:
            std::memcpy(texel.data() + c * 4, &uintValue[c], 4);
            break;
        default:
            std::memcpy(texel.data() + c * 4, &value[c], 4);
            break; // 32-bit float and depth formats
        }
    }
    return texel;
}

D3D12_TEXTURE_COPY_LOCATION subresourceLocation(Texture& texture, rhi::TextureSlice slice) {
    D3D12_TEXTURE_COPY_LOCATION location{};
    location.pResource = texture.native();
    location.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    location.SubresourceIndex = texture.subresource(slice);
    return location;
}

// Rows of `rowPitch` bytes at `offset` in `buffer`, laid out like the texture's subresource.
D3D12_TEXTURE_COPY_LOCATION footprintLocation(ID3D12Device* device, Texture& texture, rhi::TextureSlice slice,
                                              ID3D12Resource* buffer, uint64_t offset, uint32_t rowPitch) {
    const D3D12_RESOURCE_DESC desc = resourceDesc(texture.native());
    D3D12_TEXTURE_COPY_LOCATION location{};
    location.pResource = buffer;
    location.Type = D3D12_TEXTURE_COPY_TYPE_PLACED_FOOTPRINT;
    device->GetCopyableFootprints(&desc, texture.subresource(slice), 1, 0, &location.PlacedFootprint, nullptr,
                                  nullptr, nullptr);
    location.PlacedFootprint.Offset = offset;
    location.PlacedFootprint.Footprint.RowPitch = rowPitch;
    return location;
}

} // namespace

void CommandList::copyBuffer(rhi::IBuffer& dst, uint64_t dstOffset, rhi::IBuffer& src, uint64_t srcOffset,
                             uint64_t size) {
    requireOpen("copyBuffer()");
    rhi::validateBufferRange("copyBuffer (source)", src, srcOffset, size);
    rhi::validateBufferRange("copyBuffer (destination)", dst, dstOffset, size);
    if (size == 0) {
        return;
    }
    use(dst, rhi::ResourceState::CopyDest);
    use(src, rhi::ResourceState::CopySource);
    flushBarriers();
    list_->CopyBufferRegion(toBuffer(dst).native(), dstOffset, toBuffer(src).native(), srcOffset, size);
    commandRecorded();
}

void CommandList::copyBufferToTexture(rhi::ITexture& dst, rhi::TextureSlice slice, rhi::IBuffer& src,
                                      uint64_t srcOffset, uint32_t rowPitch) {
    requireOpen("copyBufferToTexture()");
    Texture& texture = toTexture(dst);
    rhi::validateBufferTextureCopy("copyBufferToTexture", dst, slice, src, srcOffset, rowPitch);
    use(dst, rhi::ResourceState::CopyDest);
    use(src, rhi::ResourceState::CopySource);
    flushBarriers();
    const D3D12_TEXTURE_COPY_LOCATION target = subresourceLocation(texture, slice);
    const D3D12_TEXTURE_COPY_LOCATION source =
        footprintLocation(context_->device(), texture, slice, toBuffer(src).native(), srcOffset, rowPitch);
    list_->CopyTextureRegion(&target, 0, 0, 0, &source, nullptr);
    commandRecorded();
}

void CommandList::copyTextureToBuffer(rhi::IBuffer& dst, uint64_t dstOffset, uint32_t rowPitch,
                                      rhi::ITexture& src, rhi::TextureSlice slice) {
    requireOpen("copyTextureToBuffer()");
    Texture& texture = toTexture(src);
    rhi::validateBufferTextureCopy("copyTextureToBuffer", src, slice, dst, dstOffset, rowPitch);
    use(dst, rhi::ResourceState::CopyDest);
    use(src, rhi::ResourceState::CopySource);
    flushBarriers();
    const D3D12_TEXTURE_COPY_LOCATION target =
        footprintLocation(context_->device(), texture, slice, toBuffer(dst).native(), dstOffset, rowPitch);
    const D3D12_TEXTURE_COPY_LOCATION source = subresourceLocation(texture, slice);
    list_->CopyTextureRegion(&target, 0, 0, 0, &source, nullptr);
    commandRecorded();
}

void CommandList::copyTexture(rhi::ITexture& dst, rhi::TextureSlice dstSlice, rhi::ITexture& src,
                              rhi::TextureSlice srcSlice) {
    requireOpen("copyTexture()");
    Texture& target = toTexture(dst);
    Texture& source = toTexture(src);
    rhi::validateTextureCopy(dst, dstSlice, src, srcSlice);
    use(dst, rhi::ResourceState::CopyDest);
    use(src, rhi::ResourceState::CopySource);
    flushBarriers();
    const D3D12_TEXTURE_COPY_LOCATION targetLocation = subresourceLocation(target, dstSlice);
    const D3D12_TEXTURE_COPY_LOCATION sourceLocation = subresourceLocation(source, srcSlice);
    list_->CopyTextureRegion(&targetLocation, 0, 0, 0, &sourceLocation, nullptr);
    commandRecorded();
}

void CommandList::writeBuffer(rhi::IBuffer& dst, const void* data, uint64_t size, uint64_t dstOffset) {
    requireOpen("writeBuffer()");
    rhi::validateBufferRange("writeBuffer", dst, dstOffset, size);
    if (size == 0) {
        return;
    }
    const UploadAllocation staging = upload_.allocate(size, kBufferCopyAlignment);
    std::memcpy(staging.cpu, data, size);
    use(dst, rhi::ResourceState::CopyDest);
    flushBarriers();
    list_->CopyBufferRegion(toBuffer(dst).native(), dstOffset, staging.resource, staging.offset, size);
    commandRecorded();
}

void CommandList::writeTexture(rhi::ITexture& dst, rhi::TextureSlice slice, const void* data) {
    requireOpen("writeTexture()");
    Texture& texture = toTexture(dst);
    rhi::validateTextureSlice("writeTexture", dst, slice);
    const uint32_t packedRow = rhi::mipExtent(texture.desc(), slice.mipLevel).width *
                               rhi::formatInfo(texture.desc().format).bytesPerTexel;
    uploadToTexture(texture, slice, data, packedRow);
}

// Rows of packedRowBytes from `data` (or, with packedRowBytes 0, copies of the one texel in
// `data`) into upload memory at the 256-byte pitch, then one CopyTextureRegion.
void CommandList::uploadToTexture(Texture& texture, rhi::TextureSlice slice, const void* data,
                                  uint32_t packedRowBytes) {
    const rhi::Extent3D extent = rhi::mipExtent(texture.desc(), slice.mipLevel);
    const uint32_t texelBytes = rhi::formatInfo(texture.desc().format).bytesPerTexel;
    const uint32_t pitch = rhi::alignedRowPitch(extent.width, texture.desc().format);
    const uint32_t rows = extent.height * extent.depth;
    const UploadAllocation staging =
        upload_.allocate(uint64_t(pitch) * rows, rhi::kTextureCopyOffsetAlignment);
    const auto* source = static_cast<const uint8_t*>(data);
    for (uint32_t row = 0; row < rows; ++row) {
        uint8_t* out = staging.cpu + size_t(row) * pitch;
        if (packedRowBytes) {
            std::memcpy(out, source + size_t(row) * packedRowBytes, packedRowBytes);
        } else {
            for (uint32_t x = 0; x < extent.width; ++x) {
                std::memcpy(out + size_t(x) * texelBytes, source, texelBytes);
            }
        }
    }
    use(texture, rhi::ResourceState::CopyDest);
    flushBarriers();
    const D3D12_TEXTURE_COPY_LOCATION target = subresourceLocation(texture, slice);
    const D3D12_TEXTURE_COPY_LOCATION sourceLocation =
        footprintLocation(context_->device(), texture, slice, staging.resource, staging.offset, pitch);
    list_->CopyTextureRegion(&target, 0, 0, 0, &sourceLocation, nullptr);
    commandRecorded();
}

void CommandList::clearTextureByCopy(Texture& texture, const std::array<uint8_t, 16>& texel) {
    const rhi::TextureDesc& desc = texture.desc();
    const uint32_t layers = desc.dimension == rhi::TextureDimension::Texture3D ? 1 : desc.arrayLayers;
    for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
        for (uint32_t layer = 0; layer < layers; ++layer) {
            uploadToTexture(texture, {mip, layer}, texel.data(), 0);
        }
    }
}

void CommandList::fillBuffer(rhi::IBuffer& dst, uint32_t value) {
    requireOpen("fillBuffer()");
    Buffer& buffer = toBuffer(dst);
    const uint64_t words = buffer.desc().size / 4;
    if (words == 0) {
        throw rhi::Error("fillBuffer('" + dst.debugName() + "'): the buffer is smaller than 4 bytes");
    }
    if (buffer.desc().memory == rhi::MemoryType::GpuOnly && listType_ != D3D12_COMMAND_LIST_TYPE_COPY &&
        words * 4 <= kLargestUavClearBytes) {
        // ClearUnorderedAccessViewUint takes the view twice: in a shader-visible heap, and in
        // a CPU-only one.
        const D3D12_CPU_DESCRIPTOR_HANDLE view = buffer.wholeRawUav();
        const DescriptorTable table = viewTables_.allocate(1);
        context_->device()->CopyDescriptorsSimple(1, table.cpu, view, D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);
        use(dst, rhi::ResourceState::UnorderedAccess);
        flushBarriers();
        const UINT values[4] = {value, value, value, value};
        list_->ClearUnorderedAccessViewUint(table.gpu, view, buffer.native(), values, 0, nullptr);
        commandRecorded();
        return;
    }
    // Copy queue, readback memory or a large buffer: copy the pattern from upload memory, one
    // chunk of it again and again.
    const uint64_t chunkWords = std::min<uint64_t>(words, kFillChunkBytes / 4);
    const UploadAllocation staging = upload_.allocate(chunkWords * 4, kBufferCopyAlignment);
    std::fill_n(reinterpret_cast<uint32_t*>(staging.cpu), chunkWords, value);
    use(dst, rhi::ResourceState::CopyDest);
    flushBarriers();
    for (uint64_t first = 0; first < words; first += chunkWords) {
        const uint64_t count = std::min(chunkWords, words - first);
        list_->CopyBufferRegion(buffer.native(), first * 4, staging.resource, staging.offset, count * 4);
    }
    commandRecorded();
}

void CommandList::clearColor(rhi::ITexture& target, std::array<float, 4> value) {
    requireOpen("clearColor()");
    Texture& texture = toTexture(target);
    const rhi::TextureDesc& desc = texture.desc();
    const rhi::FormatKind kind = rhi::formatInfo(desc.format).kind;
    if (kind == rhi::FormatKind::Depth) {
        throw rhi::Error("clearColor('" + desc.debugName + "'): a depth texture; use clearDepth");
    }
    if (kind == rhi::FormatKind::Uint) {
        clearColorUint(target,
                       {uint32_t(value[0]), uint32_t(value[1]), uint32_t(value[2]), uint32_t(value[3])});
        return;
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget) &&
        listType_ == D3D12_COMMAND_LIST_TYPE_DIRECT) {
        use(target, rhi::ResourceState::RenderTarget);
        flushBarriers();
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            list_->ClearRenderTargetView(texture.rtv(mip, 0, true), value.data(), 0, nullptr);
        }
    } else if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage) &&
               listType_ != D3D12_COMMAND_LIST_TYPE_COPY) {
        use(target, rhi::ResourceState::UnorderedAccess);
        flushBarriers();
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            const D3D12_CPU_DESCRIPTOR_HANDLE view = texture.uav(mip, nullptr);
            const DescriptorTable table = viewTables_.allocate(1);
            context_->device()->CopyDescriptorsSimple(1, table.cpu, view,
                                                      D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);
            list_->ClearUnorderedAccessViewFloat(table.gpu, view, texture.native(), value.data(), 0, nullptr);
        }
    } else {
        clearTextureByCopy(texture, encodeTexel(desc.format, value, {}));
        return;
    }
    commandRecorded();
}

void CommandList::clearColorUint(rhi::ITexture& target, std::array<uint32_t, 4> value) {
    requireOpen("clearColorUint()");
    Texture& texture = toTexture(target);
    const rhi::TextureDesc& desc = texture.desc();
    if (rhi::formatInfo(desc.format).kind != rhi::FormatKind::Uint) {
        // As Vulkan's VkClearColorValue: the bits are the value.
        clearColor(target, {std::bit_cast<float>(value[0]), std::bit_cast<float>(value[1]),
                            std::bit_cast<float>(value[2]), std::bit_cast<float>(value[3])});
        return;
    }
    const bool exactAsFloat =
        std::all_of(value.begin(), value.end(), [](uint32_t v) { return v < kExactFloatIntegers; });
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage) && listType_ != D3D12_COMMAND_LIST_TYPE_COPY) {
        use(target, rhi::ResourceState::UnorderedAccess);
        flushBarriers();
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            const D3D12_CPU_DESCRIPTOR_HANDLE view = texture.uav(mip, nullptr);
            const DescriptorTable table = viewTables_.allocate(1);
            context_->device()->CopyDescriptorsSimple(1, table.cpu, view,
                                                      D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);
            list_->ClearUnorderedAccessViewUint(table.gpu, view, texture.native(), value.data(), 0, nullptr);
        }
    } else if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget) &&
               listType_ == D3D12_COMMAND_LIST_TYPE_DIRECT && exactAsFloat) {
        const float asFloat[4] = {float(value[0]), float(value[1]), float(value[2]), float(value[3])};
        use(target, rhi::ResourceState::RenderTarget);
        flushBarriers();
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            list_->ClearRenderTargetView(texture.rtv(mip, 0, true), asFloat, 0, nullptr);
        }
    } else {
        clearTextureByCopy(texture, encodeTexel(desc.format, {}, value));
        return;
    }
    commandRecorded();
}

void CommandList::clearDepth(rhi::ITexture& target, float depth) {
    requireOpen("clearDepth()");
    Texture& texture = toTexture(target);
    const rhi::TextureDesc& desc = texture.desc();
    if (!rhi::isDepthFormat(desc.format)) {
        throw rhi::Error("clearDepth('" + desc.debugName + "'): not a depth format");
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::DepthStencil) &&
        listType_ == D3D12_COMMAND_LIST_TYPE_DIRECT) {
        use(target, rhi::ResourceState::DepthWrite);
        flushBarriers();
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            list_->ClearDepthStencilView(texture.dsv(mip, 0, true), D3D12_CLEAR_FLAG_DEPTH, depth, 0, 0,
                                         nullptr);
        }
        commandRecorded();
        return;
    }
    clearTextureByCopy(texture, encodeTexel(desc.format, {depth, 0, 0, 0}, {}));
}

} // namespace lumina::d3d12
