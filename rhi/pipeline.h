#pragma once
// Shaders and pipeline state. Graphics pipelines take no vertex input layout: vertex
// shaders pull their vertices from buffers by SV_VertexID, which keeps one HLSL source
// free of the semantic-to-location mapping that differs between compilers.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rhi/binding.h"

namespace lumina::rhi {

enum class ShaderFormat : uint8_t { Spirv, Dxil, Dxbc };

struct ShaderDesc {
    ShaderStage stage = ShaderStage::Compute;
    std::string entryPoint = "main";
    std::string debugName;
};

class IShader {
public:
    virtual ~IShader() = default;
    virtual const ShaderDesc& desc() const = 0;
};
using ShaderHandle = std::shared_ptr<IShader>;

struct ComputePipelineDesc {
    ShaderHandle shader;
    std::vector<BindingLayoutHandle> layouts; // one per register space, spaces 0..n-1 in order
    uint32_t pushConstantBytes = 0;           // a multiple of 4, at most 128
    std::string debugName;
};

enum class CullMode : uint8_t { None, Front, Back };
enum class PrimitiveTopology : uint8_t { TriangleList, TriangleStrip, LineList, PointList };

struct RasterState {
    CullMode cullMode = CullMode::Back;
    bool frontCounterClockwise = true; // glTF's convention
    bool depthClipEnable = true;
    float depthBias = 0.0f;            // constant, in units of the depth format's resolution
    float slopeScaledDepthBias = 0.0f;
    bool wireframe = false;
};

struct DepthState {
    bool testEnable = true;
    bool writeEnable = true;
    CompareOp compareOp = CompareOp::Less;
};

enum class BlendFactor : uint8_t { Zero, One, SrcAlpha, OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha, SrcColor, DstColor };
enum class BlendOp : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

struct BlendState {
    bool enable = false;
    BlendFactor srcColor = BlendFactor::One;
    BlendFactor dstColor = BlendFactor::Zero;
    BlendOp colorOp = BlendOp::Add;
    BlendFactor srcAlpha = BlendFactor::One;
    BlendFactor dstAlpha = BlendFactor::Zero;
    BlendOp alphaOp = BlendOp::Add;
    uint8_t writeMask = 0xF; // RGBA bits
};

struct GraphicsPipelineDesc {
    ShaderHandle vertexShader;
    ShaderHandle pixelShader; // may be empty for depth-only passes
    std::vector<BindingLayoutHandle> layouts;
    uint32_t pushConstantBytes = 0;
    PrimitiveTopology topology = PrimitiveTopology::TriangleList;
    RasterState raster;
    DepthState depth;
    std::vector<Format> colorFormats;
    std::vector<BlendState> blend; // one per colour target, or empty for no blending
    Format depthFormat = Format::Unknown;
    std::string debugName;
};

class IComputePipeline {
public:
    virtual ~IComputePipeline() = default;
    virtual const ComputePipelineDesc& desc() const = 0;
};
class IGraphicsPipeline {
public:
    virtual ~IGraphicsPipeline() = default;
    virtual const GraphicsPipelineDesc& desc() const = 0;
};
using ComputePipelineHandle = std::shared_ptr<IComputePipeline>;
using GraphicsPipelineHandle = std::shared_ptr<IGraphicsPipeline>;

} // namespace lumina::rhi
