#pragma once
// Binding layouts and sets, keyed by HLSL registers so that C++ and HLSL read the same:
// `RWTexture2D<float4> output : register(u0)` is bound as BindingSetItem::storageTexture(0, tex).
// On Vulkan register n of class b/t/u/s becomes binding n + 0/100/200/300 in the descriptor
// set of its register space (docs/binding.md); on D3D12 the registers build the root signature.
#include "rhi/resource.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace lumina::rhi {

enum class BindingType : uint8_t {
    ConstantBuffer, // b: cbuffer, ConstantBuffer<T>
    TextureSRV,     // t: Texture2D, Texture3D, TextureCube, ...
    BufferSRV,      // t: StructuredBuffer<T>
    RawBufferSRV,   // t: ByteAddressBuffer
    TextureUAV,     // u: RWTexture2D, RWTexture3D, RWTexture2DArray
    BufferUAV,      // u: RWStructuredBuffer<T>
    RawBufferUAV,   // u: RWByteAddressBuffer
    Sampler,        // s: SamplerState, SamplerComparisonState
};

enum class ShaderStage : uint8_t { Compute, Vertex, Pixel };

enum class ShaderStageMask : uint8_t { Compute = 1, Vertex = 2, Pixel = 4, Graphics = 6, All = 7 };

struct BindingLayoutItem {
    BindingType type;
    uint32_t reg; // the HLSL register number, within its class
};

struct BindingLayoutDesc {
    uint32_t space = 0; // HLSL register space; descriptor set index on Vulkan
    ShaderStageMask visibility = ShaderStageMask::All;
    std::vector<BindingLayoutItem> items;
};

class IBindingLayout {
public:
    virtual ~IBindingLayout() = default;
    virtual const BindingLayoutDesc& desc() const = 0;
};
using BindingLayoutHandle = std::shared_ptr<IBindingLayout>;

struct BufferRange {
    uint64_t offset = 0;
    uint64_t size = 0; // 0: to the end of the buffer
};

// A view of part of a texture: one mip for storage views, a mip range for sampled views.
struct TextureSubresources {
    uint32_t baseMip = 0;
    uint32_t mipCount = 0; // 0: all from baseMip
    uint32_t baseLayer = 0;
    uint32_t layerCount = 0; // 0: all from baseLayer
};

struct BindingSetItem {
    BindingType type = BindingType::ConstantBuffer;
    uint32_t reg = 0;
    BufferHandle buffer;
    TextureHandle texture;
    SamplerHandle sampler;
    BufferRange range;
    TextureSubresources subresources;
    // View the texture as another dimension, e.g. a cube array as a 2D array for a UAV.
    bool overrideDimension = false;
    TextureDimension viewDimension = TextureDimension::Texture2D;

    static BindingSetItem constantBuffer(uint32_t reg, BufferHandle buffer, BufferRange range = {});
    static BindingSetItem sampledTexture(uint32_t reg, TextureHandle texture, TextureSubresources sub = {});
    static BindingSetItem storageTexture(uint32_t reg, TextureHandle texture, uint32_t mip = 0);
    static BindingSetItem structuredBuffer(uint32_t reg, BufferHandle buffer, BufferRange range = {});
    static BindingSetItem rwStructuredBuffer(uint32_t reg, BufferHandle buffer, BufferRange range = {});
    static BindingSetItem rawBuffer(uint32_t reg, BufferHandle buffer, BufferRange range = {});
    static BindingSetItem rwRawBuffer(uint32_t reg, BufferHandle buffer, BufferRange range = {});
    static BindingSetItem samplerState(uint32_t reg, SamplerHandle sampler);
};

// The resources of one register space for one dispatch or draw. A value, not a GPU object:
// command lists write it into descriptors allocated per submission (a per-frame ring on
// D3D12, a pool reset per recording on Vulkan), so nothing has to outlive the frame.
struct BindingSet {
    BindingLayoutHandle layout;
    std::vector<BindingSetItem> items;
};

// The state each binding type needs its resource in, and whether it writes it.
ResourceState requiredState(BindingType type);
bool isWriteBinding(BindingType type);

// The HLSL register class of a binding type: 'b', 't', 'u' or 's'.
char registerClass(BindingType type);
// For messages: "constant buffer", "storage texture (UAV)", ...
const char* bindingTypeName(BindingType type);

} // namespace lumina::rhi
