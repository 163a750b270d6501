#pragma once
// Shaders, compute and graphics pipelines, and the PSO cache. A pipeline object carries its
// description, its root signature (d3d12_binding.h) and a pipeline state object taken from
// the cache, keyed by the shaders' bytecode, the root signature and every piece of fixed
// state, so identical pipelines made twice share one PSO.
#include "rhi/pipeline.h"
#include "rhi_d3d12/d3d12_binding.h"
#include "rhi_d3d12/d3d12_context.h"

#include <cstdint>
#include <map>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace lumina::d3d12 {

class Shader final : public rhi::IShader {
public:
    Shader(const rhi::ShaderDesc& desc, std::span<const uint8_t> bytecode, rhi::ShaderFormat format);
    const rhi::ShaderDesc& desc() const override { return desc_; }
    D3D12_SHADER_BYTECODE bytecode() const { return {bytecode_.data(), bytecode_.size()}; }
    rhi::ShaderFormat format() const { return format_; }
    uint64_t hash() const { return hash_; }

private:
    rhi::ShaderDesc desc_;
    std::vector<uint8_t> bytecode_;
    rhi::ShaderFormat format_;
    uint64_t hash_;
};

// Reads the DXBC container of a compiled shader: DXIL (a "DXIL" part) or DXBC (SHDR/SHEX).
// Throws rhi::Error naming the shader when the bytes are not a container (SPIR-V, say), or
// DXIL on a device whose highest shader model is below 6.0 (Wine's vkd3d takes DXBC only).
rhi::ShaderHandle createShader(const DeviceContext& context, const rhi::ShaderDesc& desc,
                               std::span<const uint8_t> bytecode);

class ComputePipeline final : public rhi::IComputePipeline {
public:
    ComputePipeline(rhi::ComputePipelineDesc desc, RootSignatureHandle root, ComPtr<ID3D12PipelineState> pso)
        : desc_(std::move(desc)), root_(std::move(root)), pso_(std::move(pso)) {}
    const rhi::ComputePipelineDesc& desc() const override { return desc_; }
    const RootSignature& root() const { return *root_; }
    ID3D12PipelineState* pso() const { return pso_.Get(); }
    const ComPtr<ID3D12PipelineState>& psoHandle() const { return pso_; }

private:
    rhi::ComputePipelineDesc desc_;
    RootSignatureHandle root_;
    ComPtr<ID3D12PipelineState> pso_;
};

class GraphicsPipeline final : public rhi::IGraphicsPipeline {
public:
    GraphicsPipeline(rhi::GraphicsPipelineDesc desc, RootSignatureHandle root,
                     ComPtr<ID3D12PipelineState> pso)
        : desc_(std::move(desc)), root_(std::move(root)), pso_(std::move(pso)) {}
    const rhi::GraphicsPipelineDesc& desc() const override { return desc_; }
    const RootSignature& root() const { return *root_; }
    ID3D12PipelineState* pso() const { return pso_.Get(); }
    const ComPtr<ID3D12PipelineState>& psoHandle() const { return pso_; }
    D3D12_PRIMITIVE_TOPOLOGY topology() const;

private:
    rhi::GraphicsPipelineDesc desc_;
    RootSignatureHandle root_;
    ComPtr<ID3D12PipelineState> pso_;
};

class PipelineCache {
public:
    PipelineCache(ContextHandle context, RootSignatureCache& roots)
        : context_(std::move(context)), roots_(roots) {}
    rhi::ComputePipelineHandle createCompute(const rhi::ComputePipelineDesc& desc);
    rhi::GraphicsPipelineHandle createGraphics(const rhi::GraphicsPipelineDesc& desc);
    size_t size();

private:
    ComPtr<ID3D12PipelineState> find(const std::string& key);
    void insert(const std::string& key, const ComPtr<ID3D12PipelineState>& pso);

    ContextHandle context_;
    RootSignatureCache& roots_;
    std::mutex mutex_;
    std::map<std::string, ComPtr<ID3D12PipelineState>> cache_;
};

} // namespace lumina::d3d12
