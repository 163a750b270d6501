#pragma once
// Compute and graphics pipelines. Graphics pipelines use dynamic rendering (Vulkan 1.3) and
// take no vertex input: vertex shaders pull vertices from buffers.
#include "rhi/pipeline.h"

#include <memory>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

// The VkPipelineLayout both kinds build the same way: one descriptor set per register
// space, and one push-constant range visible to every stage of the pipeline.
class PipelineLayout {
public:
    PipelineLayout(std::shared_ptr<Context> context, const std::vector<rhi::BindingLayoutHandle>& layouts,
                   uint32_t pushConstantBytes, VkShaderStageFlags stages, const std::string& debugName);
    ~PipelineLayout();
    PipelineLayout(const PipelineLayout&) = delete;
    PipelineLayout& operator=(const PipelineLayout&) = delete;

    VkPipelineLayout handle() const { return layout_; }
    VkShaderStageFlags pushConstantStages() const { return pushConstantStages_; }
    uint32_t pushConstantBytes() const { return pushConstantBytes_; }

private:
    std::shared_ptr<Context> context_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkShaderStageFlags pushConstantStages_ = 0;
    uint32_t pushConstantBytes_ = 0;
};

class ComputePipeline final : public rhi::IComputePipeline {
public:
    ComputePipeline(std::shared_ptr<Context> context, const rhi::ComputePipelineDesc& desc);
    ~ComputePipeline() override;
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    const rhi::ComputePipelineDesc& desc() const override { return desc_; }
    VkPipeline handle() const { return pipeline_; }
    const PipelineLayout& layout() const { return layout_; }

private:
    std::shared_ptr<Context> context_;
    rhi::ComputePipelineDesc desc_;
    PipelineLayout layout_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

class GraphicsPipeline final : public rhi::IGraphicsPipeline {
public:
    GraphicsPipeline(std::shared_ptr<Context> context, const rhi::GraphicsPipelineDesc& desc);
    ~GraphicsPipeline() override;
    GraphicsPipeline(const GraphicsPipeline&) = delete;
    GraphicsPipeline& operator=(const GraphicsPipeline&) = delete;

    const rhi::GraphicsPipelineDesc& desc() const override { return desc_; }
    VkPipeline handle() const { return pipeline_; }
    const PipelineLayout& layout() const { return layout_; }

private:
    std::shared_ptr<Context> context_;
    rhi::GraphicsPipelineDesc desc_;
    PipelineLayout layout_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace lumina::vulkan
