#pragma once
// Buffers, textures and samplers: descriptions and the interfaces backends implement.
#include "rhi/format.h"
#include "rhi/resource_state.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace lumina::rhi {

// Where a resource lives. Upload and Readback buffers are persistently mapped.
enum class MemoryType : uint8_t { GpuOnly, Upload, Readback };
const char* memoryTypeName(MemoryType memory); // "GpuOnly", "Upload", "Readback"

// How a buffer may be bound. Copies to and from every buffer are always allowed.
enum class BufferUsage : uint32_t {
    None = 0,
    Constant = 1u << 0,   // cbuffer / ConstantBuffer<T> (b registers)
    Structured = 1u << 1, // StructuredBuffer / RWStructuredBuffer (needs stride)
    Raw = 1u << 2,        // ByteAddressBuffer / RWByteAddressBuffer
    Storage = 1u << 3,    // may be bound read-write (u registers); GpuOnly memory only
    Index = 1u << 4,
    Indirect = 1u << 5,
};
constexpr BufferUsage operator|(BufferUsage a, BufferUsage b) {
    return static_cast<BufferUsage>(static_cast<uint32_t>(a) | static_cast<uint32_t>(b));
}
constexpr bool hasFlag(BufferUsage set, BufferUsage flag) {
    return (static_cast<uint32_t>(set) & static_cast<uint32_t>(flag)) != 0;
}

struct BufferDesc {
    uint64_t size = 0;
    uint32_t structStride = 0; // element size for Structured buffers, 0 otherwise
    BufferUsage usage = BufferUsage::None;
    MemoryType memory = MemoryType::GpuOnly;
    std::string debugName;
};

enum class TextureDimension : uint8_t { Texture2D, Texture2DArray, Texture3D, TextureCube, TextureCubeArray };
const char* textureDimensionName(TextureDimension dimension); // "Texture2D", ...
constexpr bool isCubeDimension(TextureDimension dimension) {
    return dimension == TextureDimension::TextureCube || dimension == TextureDimension::TextureCubeArray;
}

enum class TextureUsage : uint32_t {
    None = 0,
    Sampled = 1u << 0,      // Texture2D<...> (t registers)
    Storage = 1u << 1,      // RWTexture2D<...> (u registers)
    RenderTarget = 1u << 2, // colour attachment
    DepthStencil = 1u << 3, // depth attachment
};
constexpr TextureUsage operator|(TextureUsage a, TextureUsage b) {
    return static_cast<TextureUsage>(static_cast<uint32_t>(a) | static_cast<uint32_t>(b));
}
constexpr bool hasFlag(TextureUsage set, TextureUsage flag) {
    return (static_cast<uint32_t>(set) & static_cast<uint32_t>(flag)) != 0;
}

struct TextureDesc {
    TextureDimension dimension = TextureDimension::Texture2D;
    Format format = Format::RGBA8_UNORM;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t depth = 1;       // Texture3D only
    uint32_t arrayLayers = 1; // total layers: 6 for a cube, 6 x N for a cube array
    uint32_t mipLevels = 1;
    TextureUsage usage = TextureUsage::Sampled;
    std::string debugName;
};

// One mip level of one array layer (all depth slices of a 3D texture).
struct TextureSlice {
    uint32_t mipLevel = 0;
    uint32_t arrayLayer = 0;
};

inline uint32_t mipExtent(uint32_t extent, uint32_t mip) {
    return extent >> mip ? extent >> mip : 1u;
}

struct Extent3D {
    uint32_t width, height, depth;
};
// One mip of a texture; depth is 1 except for 3D textures.
inline Extent3D mipExtent(const TextureDesc& desc, uint32_t mip) {
    return {mipExtent(desc.width, mip), mipExtent(desc.height, mip),
            desc.dimension == TextureDimension::Texture3D ? mipExtent(desc.depth, mip) : 1u};
}
// The layers a TextureSlice can name: one for a 3D texture (its depth slices go together).
inline uint32_t sliceLayerCount(const TextureDesc& desc) {
    return desc.dimension == TextureDimension::Texture3D ? 1u : desc.arrayLayers;
}

// Resources share the state the command lists track (rhi/state_tracker.h). The tracked
// state is the one the resource is in after every command list recorded so far has
// executed: command lists are submitted in the order they are recorded.
class IResource {
public:
    virtual ~IResource() = default;
    virtual const std::string& debugName() const = 0;

    ResourceState trackedState = ResourceState::Undefined;
};

class IBuffer : public IResource {
public:
    virtual const BufferDesc& desc() const = 0;
    // Host pointer of an Upload or Readback buffer; throws for GpuOnly memory.
    virtual void* map() = 0;
    const std::string& debugName() const override { return desc().debugName; }
};

class ITexture : public IResource {
public:
    virtual const TextureDesc& desc() const = 0;
    const std::string& debugName() const override { return desc().debugName; }
};

enum class Filter : uint8_t { Point, Linear };
enum class AddressMode : uint8_t { Wrap, Clamp, Mirror, Border };
enum class CompareOp : uint8_t { Never, Less, LessEqual, Equal, GreaterEqual, Greater, NotEqual, Always };

struct SamplerDesc {
    Filter minFilter = Filter::Linear;
    Filter magFilter = Filter::Linear;
    Filter mipFilter = Filter::Linear;
    AddressMode addressU = AddressMode::Clamp;
    AddressMode addressV = AddressMode::Clamp;
    AddressMode addressW = AddressMode::Clamp;
    bool compareEnable = false; // SamplerComparisonState, for hardware shadow-map PCF
    CompareOp compareOp = CompareOp::LessEqual;
    float maxAnisotropy = 1.0f;
    std::string debugName;
};

class ISampler {
public:
    virtual ~ISampler() = default;
    virtual const SamplerDesc& desc() const = 0;
};

using BufferHandle = std::shared_ptr<IBuffer>;
using TextureHandle = std::shared_ptr<ITexture>;
using SamplerHandle = std::shared_ptr<ISampler>;

// Copies between textures and buffers: buffer rows are a multiple of 256 bytes apart
// (D3D12_TEXTURE_DATA_PITCH_ALIGNMENT) and start at a multiple of 512 bytes
// (D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT); rhi/validation.h holds every backend to both.
constexpr uint32_t kTextureCopyRowAlignment = 256;
constexpr uint64_t kTextureCopyOffsetAlignment = 512;
inline uint32_t alignedRowPitch(uint32_t width, Format format) {
    const uint32_t row = width * formatInfo(format).bytesPerTexel;
    return (row + kTextureCopyRowAlignment - 1) / kTextureCopyRowAlignment * kTextureCopyRowAlignment;
}

} // namespace lumina::rhi
