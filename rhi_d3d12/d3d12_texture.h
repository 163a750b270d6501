#pragma once
// Textures: committed resources in the default heap. 2D, 2D-array, cube and cube-array
// textures are one D3D12 TEXTURE2D with arrayLayers slices; views pick the dimension. Views
// are created on first use in the staging heaps (RTVs and DSVs in their own) and cached.
#include "rhi/binding.h"
#include "rhi/resource.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_state.h"

#include <cstdint>
#include <map>
#include <mutex>

namespace lumina::d3d12 {

class Texture final : public rhi::ITexture, public NativeResource {
public:
    Texture(ContextHandle context, const rhi::TextureDesc& desc);
    ~Texture() override;

    const rhi::TextureDesc& desc() const override { return desc_; }

    // D3D12 subresource index of one mip of one array layer.
    uint32_t subresource(rhi::TextureSlice slice) const;
    // Throws rhi::Error naming the texture when the slice is out of range.
    void checkSlice(rhi::TextureSlice slice, const char* what) const;

    D3D12_CPU_DESCRIPTOR_HANDLE srv(const rhi::TextureSubresources& sub,
                                    const rhi::TextureDimension* dimension);
    D3D12_CPU_DESCRIPTOR_HANDLE uav(uint32_t mip, const rhi::TextureDimension* dimension);
    // One mip of one layer (a 3D texture's depth slice); allLayers: every layer of the mip.
    D3D12_CPU_DESCRIPTOR_HANDLE rtv(uint32_t mip, uint32_t layer, bool allLayers = false);
    // readOnly: a DSV for depth testing without writes, with the texture in DEPTH_READ.
    D3D12_CPU_DESCRIPTOR_HANDLE dsv(uint32_t mip, uint32_t layer, bool allLayers = false,
                                    bool readOnly = false);

    uint32_t layerCount() const; // array layers, or depth slices of a 3D texture's mip 0

private:
    enum class ViewKind : uint8_t { Srv, Uav, Rtv, Dsv };
    struct ViewKey {
        ViewKind kind;
        rhi::TextureDimension dimension;
        uint32_t baseMip, mipCount, baseLayer, layerCount;
        bool readOnly = false;
        auto operator<=>(const ViewKey&) const = default;
    };
    D3D12_CPU_DESCRIPTOR_HANDLE cachedView(const ViewKey& key);
    D3D12_CPU_DESCRIPTOR_HANDLE createView(const ViewKey& key);
    StagingDescriptorHeap& heapFor(ViewKind kind) const;

    ContextHandle context_;
    rhi::TextureDesc desc_;
    uint64_t allocatedBytes_ = 0;
    std::mutex viewMutex_;
    std::map<ViewKey, D3D12_CPU_DESCRIPTOR_HANDLE> views_;
};

Texture& toTexture(rhi::ITexture& texture);

} // namespace lumina::d3d12
