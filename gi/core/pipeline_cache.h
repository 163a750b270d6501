#pragma once
// Pipelines keyed by kernel name and binding signature. A pass names its kernel and binds
// resources by register; the binding layouts and the pipeline follow from that, created
// once and reused every frame.
#include "rhi/rhi.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

// The resources one pass binds, per register space.
using SpaceBindings = std::vector<std::vector<rhi::BindingSetItem>>;

// Raster state of a graphics pass; shaders, formats and layouts come from the pass itself.
struct RasterPipelineState {
    rhi::RasterState raster;
    rhi::DepthState depth;
    std::vector<rhi::BlendState> blend;
    rhi::PrimitiveTopology topology = rhi::PrimitiveTopology::TriangleList;
};

class PipelineCache {
public:
    PipelineCache(rhi::IDevice& device, rhi::ShaderLibrary& shaders) : device_(device), shaders_(shaders) {}

    struct ComputeEntry {
        rhi::ComputePipelineHandle pipeline;
        std::vector<rhi::BindingLayoutHandle> layouts;
    };
    struct GraphicsEntry {
        rhi::GraphicsPipelineHandle pipeline;
        std::vector<rhi::BindingLayoutHandle> layouts;
    };

    const ComputeEntry& compute(std::string_view kernel, const SpaceBindings& bindings,
                                uint32_t pushConstantBytes);
    const GraphicsEntry& graphics(std::string_view vertexKernel, std::string_view pixelKernel,
                                  const SpaceBindings& bindings, uint32_t pushConstantBytes,
                                  const RasterPipelineState& state,
                                  const std::vector<rhi::Format>& colorFormats, rhi::Format depthFormat);

    rhi::IDevice& device() { return device_; }
    rhi::ShaderLibrary& shaders() { return shaders_; }

private:
    // Every resource the kernel's SPIR-V uses is bound at its register, as the right kind
    // (gi/core/kernel_bindings.h); run once, when the pipeline is created.
    void checkBindings(std::string_view kernel, const SpaceBindings& bindings);
    std::vector<rhi::BindingLayoutHandle> layoutsFor(const SpaceBindings& bindings, std::string& key);

    rhi::IDevice& device_;
    rhi::ShaderLibrary& shaders_;
    std::map<std::string, rhi::BindingLayoutHandle, std::less<>> layouts_;
    std::map<std::string, ComputeEntry, std::less<>> compute_;
    std::map<std::string, GraphicsEntry, std::less<>> graphics_;
};

} // namespace lumina::gi
