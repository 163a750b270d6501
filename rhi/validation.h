#pragma once
// The RHI's backend-neutral rules, checked in one place for every backend. Where the APIs
// differ, the rule is the stricter one, so that code which runs on one backend runs on the
// other: a caller that passes here never meets a backend-only refusal for the same reason.
// Each backend calls these at the top of the matching command or create call, then checks
// only what depends on its device (limits, supported formats). The rules:
//
//   buffers     size > 0; Structured usage needs a structStride; Storage usage needs GpuOnly
//               memory (D3D12's upload and readback heaps take no UAVs).
//   textures    a format; every extent, layer and mip count at least 1, mips at most the full
//               chain; depth 1 unless 3D; one layer for Texture2D and Texture3D; cubes square
//               with 6 layers per cube (exactly 6 for TextureCube); depth formats neither
//               Storage nor RenderTarget, DepthStencil only on a 2D depth format; no Storage
//               on sRGB formats (D3D12 has no sRGB UAVs). Device limits are the backend's.
//   samplers    maxAnisotropy in [1, kMaxSamplerAnisotropy] (16, D3D12's maximum; Vulkan clamped
//               to its device limit before).
//   buffer      a buffer bound through a binding set: not Readback memory (D3D12 readback
//   bindings    heaps take no views); a non-empty range inside the buffer; u registers need
//               Storage usage; a constant buffer needs Constant usage and an offset multiple of
//               kConstantBufferOffsetAlignment (256, D3D12's CBV placement; Vulkan's limit is
//               at most that); a structured buffer needs Structured usage, a structStride and
//               an offset multiple of it (D3D12 views count elements); a raw buffer needs Raw
//               usage and an offset multiple of kRawBufferOffsetAlignment (16). Vulkan's own
//               offset and range limits stay in its backend.
//   texture     a sampled texture (t register) needs Sampled usage, a storage texture
//   bindings    (u register) Storage usage; the view's mips and layers lie inside the texture.
//   copies      copyBuffer / writeBuffer ranges lie inside the buffers.
//               buffer <-> texture copies (copyBufferToTexture, copyTextureToBuffer): the slice
//               exists; the buffer offset is a multiple of kTextureCopyOffsetAlignment (512,
//               D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT; Vulkan needs only the texel size); the
//               row pitch is a multiple of kTextureCopyRowAlignment (256, D3D12's
//               D3D12_TEXTURE_DATA_PITCH_ALIGNMENT; Vulkan needs only the texel size) and at
//               least one packed row; the buffer holds every row of every depth slice.
//               copyTexture: both slices exist, with equal extents and formats.
//
// Every rule throws rhi::Error naming the command, the resources and the value that broke it.
#include "rhi/binding.h"
#include "rhi/resource.h"

#include <cstdint>

namespace lumina::rhi {

// Offsets of buffer bindings (D3D12_CONSTANT_BUFFER_DATA_PLACEMENT_ALIGNMENT; raw views start
// on 16 bytes).
constexpr uint64_t kConstantBufferOffsetAlignment = 256;
constexpr uint64_t kRawBufferOffsetAlignment = 16;

void validateBufferDesc(const BufferDesc& desc);
void validateTextureDesc(const TextureDesc& desc);

constexpr float kMaxSamplerAnisotropy = 16.0f; // D3D12_MAX_MAXANISOTROPY
void validateSamplerDesc(const SamplerDesc& desc);

// A buffer bound as `type` over `range`; returns the bytes bound (range.size 0: to the end).
uint64_t validateBufferBinding(BindingType type, const IBuffer& buffer, BufferRange range);

// A texture bound as `type` (TextureSRV or TextureUAV) over `sub` (a storage view: one mip).
void validateTextureBinding(BindingType type, const ITexture& texture, const TextureSubresources& sub);

// [offset, offset + size) inside `buffer`.
void validateBufferRange(const char* command, const IBuffer& buffer, uint64_t offset, uint64_t size);

// Mip `slice.mipLevel` and layer `slice.arrayLayer` exist (a 3D texture has one layer).
void validateTextureSlice(const char* command, const ITexture& texture, TextureSlice slice);

// The buffer side of copyBufferToTexture and copyTextureToBuffer.
void validateBufferTextureCopy(const char* command, const ITexture& texture, TextureSlice slice,
                               const IBuffer& buffer, uint64_t offset, uint32_t rowPitch);

void validateTextureCopy(const ITexture& dst, TextureSlice dstSlice, const ITexture& src,
                         TextureSlice srcSlice);

} // namespace lumina::rhi
