#include "rhi_d3d12/d3d12_pipeline.h"

#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_format.h"
#include "rhi_d3d12/d3d12_sampler.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace lumina::d3d12 {

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr uint32_t kShaderModel6 = 0x60;

uint32_t fourcc(const char (&text)[5]) {
    return uint32_t(uint8_t(text[0])) | uint32_t(uint8_t(text[1])) << 8 | uint32_t(uint8_t(text[2])) << 16 |
           uint32_t(uint8_t(text[3])) << 24;
}

uint32_t readU32(std::span<const uint8_t> bytes, size_t offset) {
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

// FNV-1a, for PSO cache keys.
uint64_t fnv1a(std::span<const uint8_t> bytes) {
    uint64_t hash = 0xcbf29ce484222325ull;
    for (uint8_t byte : bytes) {
        hash = (hash ^ byte) * 0x100000001b3ull;
    }
    return hash;
}

// The container format: header "DXBC", 16-byte digest, version, total size, part count, part
// offsets; each part starts with its fourcc and size.
rhi::ShaderFormat containerFormat(std::span<const uint8_t> bytes, const std::string& name) {
    constexpr size_t kHeaderSize = 32;
    if (bytes.size() >= 4 && readU32(bytes, 0) == kSpirvMagic) {
        throw rhi::Error("createShader('" + name +
                         "'): this is SPIR-V; the D3D12 backend takes DXIL or DXBC");
    }
    if (bytes.size() < kHeaderSize || readU32(bytes, 0) != fourcc("DXBC")) {
        throw rhi::Error("createShader('" + name + "'): not a DXIL/DXBC container (" +
                         std::to_string(bytes.size()) + " bytes)");
    }
    const uint32_t parts = readU32(bytes, 28);
    if (kHeaderSize + size_t(parts) * 4 > bytes.size()) {
        throw rhi::Error("createShader('" + name + "'): truncated container");
    }
    bool dxbc = false;
    for (uint32_t i = 0; i < parts; ++i) {
        const uint32_t offset = readU32(bytes, kHeaderSize + size_t(i) * 4);
        if (size_t(offset) + 4 > bytes.size()) {
            throw rhi::Error("createShader('" + name + "'): container part " + std::to_string(i) +
                             " out of range");
        }
        const uint32_t part = readU32(bytes, offset);
        if (part == fourcc("DXIL")) {
            return rhi::ShaderFormat::Dxil;
        }
        dxbc = dxbc || part == fourcc("SHDR") || part == fourcc("SHEX");
    }
    if (!dxbc) {
        throw rhi::Error("createShader('" + name + "'): the container holds no DXIL or DXBC program");
    }
    return rhi::ShaderFormat::Dxbc;
}

template <typename T>
void appendKey(std::string& key, const T& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof value);
}

const Shader& toShader(const rhi::ShaderHandle& shader, rhi::ShaderStage stage, const std::string& pipeline) {
    const auto* native = dynamic_cast<const Shader*>(shader.get());
    if (!native) {
        throw rhi::Error("pipeline '" + pipeline + "': shader is missing or from another backend");
    }
    if (native->desc().stage != stage) {
        throw rhi::Error("pipeline '" + pipeline + "': shader '" + native->desc().debugName +
                         "' was created for another stage");
    }
    return *native;
}

D3D12_BLEND blendFactor(rhi::BlendFactor factor) {
    switch (factor) {
    case rhi::BlendFactor::Zero:
        return D3D12_BLEND_ZERO;
    case rhi::BlendFactor::One:
        return D3D12_BLEND_ONE;
    case rhi::BlendFactor::SrcAlpha:
        return D3D12_BLEND_SRC_ALPHA;
    case rhi::BlendFactor::OneMinusSrcAlpha:
        return D3D12_BLEND_INV_SRC_ALPHA;
    case rhi::BlendFactor::DstAlpha:
        return D3D12_BLEND_DEST_ALPHA;
    case rhi::BlendFactor::OneMinusDstAlpha:
        return D3D12_BLEND_INV_DEST_ALPHA;
    case rhi::BlendFactor::SrcColor:
        return D3D12_BLEND_SRC_COLOR;
    case rhi::BlendFactor::DstColor:
        return D3D12_BLEND_DEST_COLOR;
    }
    return D3D12_BLEND_ONE;
}

D3D12_BLEND_OP blendOp(rhi::BlendOp op) {
    switch (op) {
    case rhi::BlendOp::Add:
        return D3D12_BLEND_OP_ADD;
    case rhi::BlendOp::Subtract:
        return D3D12_BLEND_OP_SUBTRACT;
    case rhi::BlendOp::ReverseSubtract:
        return D3D12_BLEND_OP_REV_SUBTRACT;
    case rhi::BlendOp::Min:
        return D3D12_BLEND_OP_MIN;
    case rhi::BlendOp::Max:
        return D3D12_BLEND_OP_MAX;
    }
    return D3D12_BLEND_OP_ADD;
}

D3D12_PRIMITIVE_TOPOLOGY_TYPE topologyType(rhi::PrimitiveTopology topology) {
    switch (topology) {
    case rhi::PrimitiveTopology::TriangleList:
    case rhi::PrimitiveTopology::TriangleStrip:
        return D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE;
    case rhi::PrimitiveTopology::LineList:
        return D3D12_PRIMITIVE_TOPOLOGY_TYPE_LINE;
    case rhi::PrimitiveTopology::PointList:
        return D3D12_PRIMITIVE_TOPOLOGY_TYPE_POINT;
    }
    return D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE;
}

D3D12_RENDER_TARGET_BLEND_DESC targetBlend(const rhi::BlendState& blend) {
    D3D12_RENDER_TARGET_BLEND_DESC desc{};
    desc.BlendEnable = blend.enable;
    desc.SrcBlend = blendFactor(blend.srcColor);
    desc.DestBlend = blendFactor(blend.dstColor);
    desc.BlendOp = blendOp(blend.colorOp);
    desc.SrcBlendAlpha = blendFactor(blend.srcAlpha);
    desc.DestBlendAlpha = blendFactor(blend.dstAlpha);
    desc.BlendOpAlpha = blendOp(blend.alphaOp);
    desc.LogicOp = D3D12_LOGIC_OP_NOOP;
    desc.RenderTargetWriteMask = blend.writeMask;
    return desc;
}

} // namespace

Shader::Shader(const rhi::ShaderDesc& desc, std::span<const uint8_t> bytecode, rhi::ShaderFormat format)
    : desc_(desc), bytecode_(bytecode.begin(), bytecode.end()), format_(format), hash_(fnv1a(bytecode)) {}

rhi::ShaderHandle createShader(const DeviceContext& context, const rhi::ShaderDesc& desc,
                               std::span<const uint8_t> bytecode) {
    const rhi::ShaderFormat format = containerFormat(bytecode, desc.debugName);
    if (format == rhi::ShaderFormat::Dxil && context.highestShaderModel < kShaderModel6) {
        char model[8];
        std::snprintf(model, sizeof model, "%u.%u", context.highestShaderModel >> 4,
                      context.highestShaderModel & 0xF);
        throw rhi::Error("createShader('" + desc.debugName +
                         "'): DXIL needs shader model 6.0, this device offers " + model +
                         " and takes DXBC only (e.g. Wine's vkd3d)");
    }
    return std::make_shared<Shader>(desc, bytecode, format);
}

D3D12_PRIMITIVE_TOPOLOGY GraphicsPipeline::topology() const {
    switch (desc_.topology) {
    case rhi::PrimitiveTopology::TriangleList:
        return D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
    case rhi::PrimitiveTopology::TriangleStrip:
        return D3D_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP;
    case rhi::PrimitiveTopology::LineList:
        return D3D_PRIMITIVE_TOPOLOGY_LINELIST;
    case rhi::PrimitiveTopology::PointList:
        return D3D_PRIMITIVE_TOPOLOGY_POINTLIST;
    }
    return D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
}

ComPtr<ID3D12PipelineState> PipelineCache::find(const std::string& key) {
    std::lock_guard lock(mutex_);
    const auto it = cache_.find(key);
    return it == cache_.end() ? nullptr : it->second;
}

void PipelineCache::insert(const std::string& key, const ComPtr<ID3D12PipelineState>& pso) {
    std::lock_guard lock(mutex_);
    cache_.emplace(key, pso);
}

size_t PipelineCache::size() {
    std::lock_guard lock(mutex_);
    return cache_.size();
}

rhi::ComputePipelineHandle PipelineCache::createCompute(const rhi::ComputePipelineDesc& desc) {
    const Shader& shader = toShader(desc.shader, rhi::ShaderStage::Compute, desc.debugName);
    RootSignatureHandle root = roots_.get(desc.layouts, desc.pushConstantBytes, desc.debugName);
    std::string key = "cs:" + root->key + ":";
    appendKey(key, shader.hash());
    ComPtr<ID3D12PipelineState> pso = find(key);
    if (!pso) {
        D3D12_COMPUTE_PIPELINE_STATE_DESC stateDesc{};
        stateDesc.pRootSignature = root->native.Get();
        stateDesc.CS = shader.bytecode();
        check(context_->device()->CreateComputePipelineState(&stateDesc, IID_PPV_ARGS(&pso)),
              "ID3D12Device::CreateComputePipelineState('" + desc.debugName + "', shader '" +
                  shader.desc().debugName + "')",
              *context_);
        setDebugName(pso.Get(), desc.debugName);
        insert(key, pso);
    }
    return std::make_shared<ComputePipeline>(desc, std::move(root), std::move(pso));
}

rhi::GraphicsPipelineHandle PipelineCache::createGraphics(const rhi::GraphicsPipelineDesc& desc) {
    const Shader& vertex = toShader(desc.vertexShader, rhi::ShaderStage::Vertex, desc.debugName);
    const Shader* pixel =
        desc.pixelShader ? &toShader(desc.pixelShader, rhi::ShaderStage::Pixel, desc.debugName) : nullptr;
    if (desc.colorFormats.size() > D3D12_SIMULTANEOUS_RENDER_TARGET_COUNT) {
        throw rhi::Error("pipeline '" + desc.debugName + "': more than 8 colour targets");
    }
    if (!desc.blend.empty() && desc.blend.size() != desc.colorFormats.size()) {
        throw rhi::Error("pipeline '" + desc.debugName + "': " + std::to_string(desc.blend.size()) +
                         " blend states for " + std::to_string(desc.colorFormats.size()) + " colour targets");
    }
    RootSignatureHandle root = roots_.get(desc.layouts, desc.pushConstantBytes, desc.debugName);

    D3D12_GRAPHICS_PIPELINE_STATE_DESC stateDesc{};
    stateDesc.pRootSignature = root->native.Get();
    stateDesc.VS = vertex.bytecode();
    if (pixel) {
        stateDesc.PS = pixel->bytecode();
    }
    stateDesc.BlendState.IndependentBlendEnable = TRUE;
    for (size_t i = 0; i < D3D12_SIMULTANEOUS_RENDER_TARGET_COUNT; ++i) {
        stateDesc.BlendState.RenderTarget[i] =
            targetBlend(i < desc.blend.size() ? desc.blend[i] : rhi::BlendState{});
    }
    stateDesc.SampleMask = UINT_MAX;
    D3D12_RASTERIZER_DESC& raster = stateDesc.RasterizerState;
    raster.FillMode = desc.raster.wireframe ? D3D12_FILL_MODE_WIREFRAME : D3D12_FILL_MODE_SOLID;
    raster.CullMode = desc.raster.cullMode == rhi::CullMode::None    ? D3D12_CULL_MODE_NONE
                      : desc.raster.cullMode == rhi::CullMode::Front ? D3D12_CULL_MODE_FRONT
                                                                     : D3D12_CULL_MODE_BACK;
    raster.FrontCounterClockwise = desc.raster.frontCounterClockwise;
    raster.DepthBias = static_cast<INT>(std::lround(desc.raster.depthBias));
    raster.DepthBiasClamp = 0.0f;
    raster.SlopeScaledDepthBias = desc.raster.slopeScaledDepthBias;
    raster.DepthClipEnable = desc.raster.depthClipEnable;
    D3D12_DEPTH_STENCIL_DESC& depth = stateDesc.DepthStencilState;
    const bool hasDepth = desc.depthFormat != rhi::Format::Unknown;
    depth.DepthEnable = hasDepth && desc.depth.testEnable;
    depth.DepthWriteMask =
        hasDepth && desc.depth.writeEnable ? D3D12_DEPTH_WRITE_MASK_ALL : D3D12_DEPTH_WRITE_MASK_ZERO;
    depth.DepthFunc = toD3D12(desc.depth.compareOp);
    stateDesc.PrimitiveTopologyType = topologyType(desc.topology);
    stateDesc.NumRenderTargets = static_cast<UINT>(desc.colorFormats.size());
    for (size_t i = 0; i < desc.colorFormats.size(); ++i) {
        stateDesc.RTVFormats[i] = dxgiFormats(desc.colorFormats[i]).rtv;
        if (stateDesc.RTVFormats[i] == DXGI_FORMAT_UNKNOWN) {
            throw rhi::Error("pipeline '" + desc.debugName + "': colour target " + std::to_string(i) +
                             " has format " + std::string(rhi::formatInfo(desc.colorFormats[i]).name) +
                             ", not a colour format");
        }
    }
    if (hasDepth) {
        stateDesc.DSVFormat = dxgiFormats(desc.depthFormat).dsv;
        if (stateDesc.DSVFormat == DXGI_FORMAT_UNKNOWN) {
            throw rhi::Error("pipeline '" + desc.debugName + "': depth format " +
                             std::string(rhi::formatInfo(desc.depthFormat).name) + " is not a depth format");
        }
    }
    stateDesc.SampleDesc.Count = 1;

    // The key holds everything the description above was built from, so equal keys build
    // equal PSOs.
    std::string key = "gfx:" + root->key + ":";
    appendKey(key, vertex.hash());
    appendKey(key, pixel ? pixel->hash() : uint64_t(0));
    appendKey(key, stateDesc.BlendState);
    appendKey(key, stateDesc.RasterizerState);
    appendKey(key, stateDesc.DepthStencilState);
    appendKey(key, stateDesc.PrimitiveTopologyType);
    appendKey(key, stateDesc.NumRenderTargets);
    appendKey(key, stateDesc.RTVFormats);
    appendKey(key, stateDesc.DSVFormat);
    ComPtr<ID3D12PipelineState> pso = find(key);
    if (!pso) {
        check(context_->device()->CreateGraphicsPipelineState(&stateDesc, IID_PPV_ARGS(&pso)),
              "ID3D12Device::CreateGraphicsPipelineState('" + desc.debugName + "')", *context_);
        setDebugName(pso.Get(), desc.debugName);
        insert(key, pso);
    }
    return std::make_shared<GraphicsPipeline>(desc, std::move(root), std::move(pso));
}

} // namespace lumina::d3d12
