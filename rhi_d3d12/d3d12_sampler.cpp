#include "rhi_d3d12/d3d12_sampler.h"

#include "rhi/error.h"
#include "rhi/validation.h"

#include <algorithm>
#include <string>

namespace lumina::d3d12 {

namespace {

D3D12_FILTER_TYPE filterType(rhi::Filter filter) {
    return filter == rhi::Filter::Linear ? D3D12_FILTER_TYPE_LINEAR : D3D12_FILTER_TYPE_POINT;
}

D3D12_TEXTURE_ADDRESS_MODE addressMode(rhi::AddressMode mode) {
    switch (mode) {
    case rhi::AddressMode::Wrap:
        return D3D12_TEXTURE_ADDRESS_MODE_WRAP;
    case rhi::AddressMode::Clamp:
        return D3D12_TEXTURE_ADDRESS_MODE_CLAMP;
    case rhi::AddressMode::Mirror:
        return D3D12_TEXTURE_ADDRESS_MODE_MIRROR;
    case rhi::AddressMode::Border:
        return D3D12_TEXTURE_ADDRESS_MODE_BORDER;
    }
    return D3D12_TEXTURE_ADDRESS_MODE_CLAMP;
}

} // namespace

D3D12_COMPARISON_FUNC toD3D12(rhi::CompareOp op) {
    switch (op) {
    case rhi::CompareOp::Never:
        return D3D12_COMPARISON_FUNC_NEVER;
    case rhi::CompareOp::Less:
        return D3D12_COMPARISON_FUNC_LESS;
    case rhi::CompareOp::LessEqual:
        return D3D12_COMPARISON_FUNC_LESS_EQUAL;
    case rhi::CompareOp::Equal:
        return D3D12_COMPARISON_FUNC_EQUAL;
    case rhi::CompareOp::GreaterEqual:
        return D3D12_COMPARISON_FUNC_GREATER_EQUAL;
    case rhi::CompareOp::Greater:
        return D3D12_COMPARISON_FUNC_GREATER;
    case rhi::CompareOp::NotEqual:
        return D3D12_COMPARISON_FUNC_NOT_EQUAL;
    case rhi::CompareOp::Always:
        return D3D12_COMPARISON_FUNC_ALWAYS;
    }
    return D3D12_COMPARISON_FUNC_ALWAYS;
}

Sampler::Sampler(ContextHandle context, const rhi::SamplerDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateSamplerDesc(desc);
    const D3D12_FILTER_REDUCTION_TYPE reduction =
        desc.compareEnable ? D3D12_FILTER_REDUCTION_TYPE_COMPARISON : D3D12_FILTER_REDUCTION_TYPE_STANDARD;
    D3D12_SAMPLER_DESC sampler{};
    sampler.Filter = desc.maxAnisotropy > 1.0f
                         ? D3D12_ENCODE_ANISOTROPIC_FILTER(reduction)
                         : D3D12_ENCODE_BASIC_FILTER(filterType(desc.minFilter), filterType(desc.magFilter),
                                                     filterType(desc.mipFilter), reduction);
    sampler.AddressU = addressMode(desc.addressU);
    sampler.AddressV = addressMode(desc.addressV);
    sampler.AddressW = addressMode(desc.addressW);
    sampler.MipLODBias = 0.0f;
    sampler.MaxAnisotropy = static_cast<UINT>(std::max(1.0f, desc.maxAnisotropy));
    sampler.ComparisonFunc = desc.compareEnable ? toD3D12(desc.compareOp) : D3D12_COMPARISON_FUNC_NEVER;
    // Border colour: transparent black, the one Vulkan offers without a custom-colour extension.
    sampler.MinLOD = 0.0f;
    sampler.MaxLOD = D3D12_FLOAT32_MAX;
    descriptor_ = context_->stagingSamplers().allocate();
    context_->device()->CreateSampler(&sampler, descriptor_);
}

Sampler::~Sampler() {
    context_->stagingSamplers().free(descriptor_);
}

Sampler& toSampler(rhi::ISampler& sampler) {
    if (auto* native = dynamic_cast<Sampler*>(&sampler)) {
        return *native;
    }
    throw rhi::Error("sampler '" + sampler.desc().debugName + "' does not belong to a D3D12 device");
}

} // namespace lumina::d3d12
