#pragma once
// Samplers: one descriptor in the CPU-only sampler heap, copied into the shader-visible
// sampler heap when a binding set uses it.
#include "rhi/resource.h"
#include "rhi_d3d12/d3d12_context.h"

namespace lumina::d3d12 {

class Sampler final : public rhi::ISampler {
public:
    Sampler(ContextHandle context, const rhi::SamplerDesc& desc);
    ~Sampler() override;
    const rhi::SamplerDesc& desc() const override { return desc_; }
    D3D12_CPU_DESCRIPTOR_HANDLE descriptor() const { return descriptor_; }

private:
    ContextHandle context_;
    rhi::SamplerDesc desc_;
    D3D12_CPU_DESCRIPTOR_HANDLE descriptor_{};
};

Sampler& toSampler(rhi::ISampler& sampler);
D3D12_COMPARISON_FUNC toD3D12(rhi::CompareOp op);

} // namespace lumina::d3d12
