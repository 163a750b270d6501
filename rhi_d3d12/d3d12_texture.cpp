#include "rhi_d3d12/d3d12_texture.h"

#include "rhi/validation.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_format.h"

#include <algorithm>
#include <string>

namespace lumina::d3d12 {

namespace {

constexpr UINT kAllRemaining = UINT(-1);

std::string describe(const rhi::TextureDesc& desc) {
    return "texture '" + desc.debugName + "'";
}

} // namespace

Texture::Texture(ContextHandle context, const rhi::TextureDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateTextureDesc(desc);
    const DxgiFormats& formats = dxgiFormats(desc.format);
    const bool is3D = desc.dimension == rhi::TextureDimension::Texture3D;
    const uint32_t largest = std::max({desc.width, desc.height, is3D ? desc.depth : 1u});
    const uint32_t maxExtent =
        is3D ? D3D12_REQ_TEXTURE3D_U_V_OR_W_DIMENSION : D3D12_REQ_TEXTURE2D_U_OR_V_DIMENSION;
    if (largest > maxExtent || (!is3D && desc.arrayLayers > D3D12_REQ_TEXTURE2D_ARRAY_AXIS_DIMENSION)) {
        throw rhi::Error("createTexture('" + desc.debugName + "'): " + std::to_string(largest) +
                         " texels or " + std::to_string(desc.arrayLayers) +
                         " layers exceed D3D12's limits (" + std::to_string(maxExtent) + ", 2048 layers)");
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage) && formats.uav == DXGI_FORMAT_UNKNOWN) {
        throw rhi::Error("createTexture('" + desc.debugName + "'): format " +
                         std::string(rhi::formatInfo(desc.format).name) +
                         " takes no UAVs on D3D12 (Storage usage)");
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget) && formats.rtv == DXGI_FORMAT_UNKNOWN) {
        throw rhi::Error("createTexture('" + desc.debugName + "'): format " +
                         std::string(rhi::formatInfo(desc.format).name) + " is not a colour render target");
    }

    D3D12_RESOURCE_DESC resourceDesc{};
    resourceDesc.Dimension = is3D ? D3D12_RESOURCE_DIMENSION_TEXTURE3D : D3D12_RESOURCE_DIMENSION_TEXTURE2D;
    resourceDesc.Width = desc.width;
    resourceDesc.Height = desc.height;
    resourceDesc.DepthOrArraySize = static_cast<UINT16>(is3D ? desc.depth : desc.arrayLayers);
    resourceDesc.MipLevels = static_cast<UINT16>(desc.mipLevels);
    resourceDesc.Format = formats.resource;
    resourceDesc.SampleDesc.Count = 1;
    resourceDesc.Layout = D3D12_TEXTURE_LAYOUT_UNKNOWN;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage)) {
        resourceDesc.Flags |= D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget)) {
        resourceDesc.Flags |= D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET;
    }
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::DepthStencil)) {
        resourceDesc.Flags |= D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL;
        if (!rhi::hasFlag(desc.usage, rhi::TextureUsage::Sampled)) {
            resourceDesc.Flags |= D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE;
        }
    }
    resource_ = context_->createCommittedResource(
        D3D12_HEAP_TYPE_DEFAULT, resourceDesc, D3D12_RESOURCE_STATE_COMMON, desc.debugName, allocatedBytes_);
    currentState = D3D12_RESOURCE_STATE_COMMON;
}

Texture::~Texture() {
    for (const auto& [key, handle] : views_) {
        heapFor(key.kind).free(handle);
    }
    context_->releaseMemory(allocatedBytes_);
}

uint32_t Texture::layerCount() const {
    return desc_.dimension == rhi::TextureDimension::Texture3D ? desc_.depth : desc_.arrayLayers;
}

uint32_t Texture::subresource(rhi::TextureSlice slice) const {
    return slice.mipLevel + slice.arrayLayer * desc_.mipLevels;
}

void Texture::checkSlice(rhi::TextureSlice slice, const char* what) const {
    rhi::validateTextureSlice(what, *this, slice);
}

StagingDescriptorHeap& Texture::heapFor(ViewKind kind) const {
    switch (kind) {
    case ViewKind::Rtv:
        return context_->renderTargetViews();
    case ViewKind::Dsv:
        return context_->depthStencilViews();
    default:
        return context_->stagingViews();
    }
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::srv(const rhi::TextureSubresources& sub,
                                         const rhi::TextureDimension* dimension) {
    rhi::validateTextureBinding(rhi::BindingType::TextureSRV, *this, sub);
    const uint32_t layers = rhi::sliceLayerCount(desc_);
    const uint32_t mips = sub.mipCount ? sub.mipCount : desc_.mipLevels - sub.baseMip;
    const uint32_t count = sub.layerCount ? sub.layerCount : layers - sub.baseLayer;
    return cachedView(
        {ViewKind::Srv, dimension ? *dimension : desc_.dimension, sub.baseMip, mips, sub.baseLayer, count});
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::uav(uint32_t mip, const rhi::TextureDimension* dimension) {
    rhi::validateTextureBinding(rhi::BindingType::TextureUAV, *this, {.baseMip = mip, .mipCount = 1});
    rhi::TextureDimension viewDimension = dimension ? *dimension : desc_.dimension;
    if (rhi::isCubeDimension(viewDimension)) {
        viewDimension = rhi::TextureDimension::Texture2DArray; // UAVs of cubes are 2D arrays
    }
    const uint32_t layers = desc_.dimension == rhi::TextureDimension::Texture3D
                                ? rhi::mipExtent(desc_.depth, mip)
                                : desc_.arrayLayers;
    return cachedView({ViewKind::Uav, viewDimension, mip, 1, 0, layers});
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::rtv(uint32_t mip, uint32_t layer, bool allLayers) {
    if (!rhi::hasFlag(desc_.usage, rhi::TextureUsage::RenderTarget)) {
        throw rhi::Error(describe(desc_) +
                         " is used as a render target but lacks TextureUsage::RenderTarget");
    }
    checkSlice({mip, desc_.dimension == rhi::TextureDimension::Texture3D ? 0 : layer}, "render target");
    const uint32_t layers = desc_.dimension == rhi::TextureDimension::Texture3D
                                ? rhi::mipExtent(desc_.depth, mip)
                                : desc_.arrayLayers;
    return cachedView(
        {ViewKind::Rtv, desc_.dimension, mip, 1, allLayers ? 0 : layer, allLayers ? layers : 1});
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::dsv(uint32_t mip, uint32_t layer, bool allLayers, bool readOnly) {
    if (!rhi::hasFlag(desc_.usage, rhi::TextureUsage::DepthStencil)) {
        throw rhi::Error(describe(desc_) + " is used as a depth target but lacks TextureUsage::DepthStencil");
    }
    checkSlice({mip, layer}, "depth target");
    return cachedView({ViewKind::Dsv, desc_.dimension, mip, 1, allLayers ? 0 : layer,
                       allLayers ? desc_.arrayLayers : 1, readOnly});
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::cachedView(const ViewKey& key) {
    std::lock_guard lock(viewMutex_);
    if (const auto it = views_.find(key); it != views_.end()) {
        return it->second;
    }
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = createView(key);
    views_.emplace(key, handle);
    return handle;
}

D3D12_CPU_DESCRIPTOR_HANDLE Texture::createView(const ViewKey& key) {
    const DxgiFormats& formats = dxgiFormats(desc_.format);
    ID3D12Device* device = context_->device();
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = heapFor(key.kind).allocate();
    using Dim = rhi::TextureDimension;
    switch (key.kind) {
    case ViewKind::Srv: {
        D3D12_SHADER_RESOURCE_VIEW_DESC view{};
        view.Format = formats.srv;
        view.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
        switch (key.dimension) {
        case Dim::Texture2D:
            view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2D;
            if (key.baseLayer != 0) { // one layer of an array, viewed as 2D
                view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2DARRAY;
                view.Texture2DArray = {key.baseMip, key.mipCount, key.baseLayer, 1, 0, 0.0f};
            } else {
                view.Texture2D = {key.baseMip, key.mipCount, 0, 0.0f};
            }
            break;
        case Dim::Texture2DArray:
            view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2DARRAY;
            view.Texture2DArray = {key.baseMip, key.mipCount, key.baseLayer, key.layerCount, 0, 0.0f};
            break;
        case Dim::Texture3D:
            view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE3D;
            view.Texture3D = {key.baseMip, key.mipCount, 0.0f};
            break;
        case Dim::TextureCube:
            view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURECUBE;
            view.TextureCube = {key.baseMip, key.mipCount, 0.0f};
            break;
        case Dim::TextureCubeArray:
            view.ViewDimension = D3D12_SRV_DIMENSION_TEXTURECUBEARRAY;
            view.TextureCubeArray = {key.baseMip, key.mipCount, key.baseLayer, key.layerCount / 6, 0.0f};
            break;
        }
        device->CreateShaderResourceView(resource_.Get(), &view, handle);
        break;
    }
    case ViewKind::Uav: {
        D3D12_UNORDERED_ACCESS_VIEW_DESC view{};
        view.Format = formats.uav;
        if (key.dimension == Dim::Texture3D) {
            view.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE3D;
            view.Texture3D = {key.baseMip, 0, kAllRemaining};
        } else if (key.dimension == Dim::Texture2D && key.layerCount == 1) {
            view.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
            view.Texture2D = {key.baseMip, 0};
        } else {
            view.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2DARRAY;
            view.Texture2DArray = {key.baseMip, key.baseLayer, key.layerCount, 0};
        }
        device->CreateUnorderedAccessView(resource_.Get(), nullptr, &view, handle);
        break;
    }
    case ViewKind::Rtv: {
        D3D12_RENDER_TARGET_VIEW_DESC view{};
        view.Format = formats.rtv;
        if (desc_.dimension == Dim::Texture3D) {
            view.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE3D;
            view.Texture3D = {key.baseMip, key.baseLayer, key.layerCount};
        } else if (desc_.dimension == Dim::Texture2D) {
            view.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2D;
            view.Texture2D = {key.baseMip, 0};
        } else {
            view.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2DARRAY;
            view.Texture2DArray = {key.baseMip, key.baseLayer, key.layerCount, 0};
        }
        device->CreateRenderTargetView(resource_.Get(), &view, handle);
        break;
    }
    case ViewKind::Dsv: {
        D3D12_DEPTH_STENCIL_VIEW_DESC view{};
        view.Format = formats.dsv;
        view.Flags = key.readOnly ? D3D12_DSV_FLAG_READ_ONLY_DEPTH : D3D12_DSV_FLAG_NONE;
        if (desc_.dimension == Dim::Texture2D) {
            view.ViewDimension = D3D12_DSV_DIMENSION_TEXTURE2D;
            view.Texture2D = {key.baseMip};
        } else {
            view.ViewDimension = D3D12_DSV_DIMENSION_TEXTURE2DARRAY;
            view.Texture2DArray = {key.baseMip, key.baseLayer, key.layerCount};
        }
        device->CreateDepthStencilView(resource_.Get(), &view, handle);
        break;
    }
    }
    return handle;
}

Texture& toTexture(rhi::ITexture& texture) {
    if (auto* native = dynamic_cast<Texture*>(&texture)) {
        return *native;
    }
    throw rhi::Error("texture '" + texture.debugName() + "' does not belong to a D3D12 device");
}

} // namespace lumina::d3d12
