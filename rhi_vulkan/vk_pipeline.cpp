#include "rhi_vulkan/vk_pipeline.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_binding.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_format.h"
#include "rhi_vulkan/vk_sampler.h"
#include "rhi_vulkan/vk_shader.h"
#include "rhi_vulkan/vk_struct.h"

#include <cstring>
#include <string>
#include <vector>

namespace lumina::vulkan {

namespace {

const Shader& vulkanShader(const rhi::ShaderHandle& shader, rhi::ShaderStage stage,
                           const std::string& pipeline, const char* role) {
    const auto* vk = dynamic_cast<const Shader*>(shader.get());
    if (!vk) {
        throw rhi::Error("pipeline '" + pipeline + "': no " + role + " shader of this backend");
    }
    if (vk->desc().stage != stage) {
        throw rhi::Error("pipeline '" + pipeline + "': shader '" + vk->desc().debugName + "' is not a " +
                         role + " shader");
    }
    return *vk;
}

VkPipelineShaderStageCreateInfo stageInfo(const Shader& shader) {
    auto info =
        vkStruct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    info.stage = shader.stage();
    info.module = shader.handle();
    info.pName = shader.desc().entryPoint.c_str();
    return info;
}

VkBlendFactor toVkBlendFactor(rhi::BlendFactor factor) {
    switch (factor) {
    case rhi::BlendFactor::Zero:
        return VK_BLEND_FACTOR_ZERO;
    case rhi::BlendFactor::One:
        return VK_BLEND_FACTOR_ONE;
    case rhi::BlendFactor::SrcAlpha:
        return VK_BLEND_FACTOR_SRC_ALPHA;
    case rhi::BlendFactor::OneMinusSrcAlpha:
        return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case rhi::BlendFactor::DstAlpha:
        return VK_BLEND_FACTOR_DST_ALPHA;
    case rhi::BlendFactor::OneMinusDstAlpha:
        return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    case rhi::BlendFactor::SrcColor:
        return VK_BLEND_FACTOR_SRC_COLOR;
    case rhi::BlendFactor::DstColor:
        return VK_BLEND_FACTOR_DST_COLOR;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkBlendOp toVkBlendOp(rhi::BlendOp op) {
    switch (op) {
    case rhi::BlendOp::Add:
        return VK_BLEND_OP_ADD;
    case rhi::BlendOp::Subtract:
        return VK_BLEND_OP_SUBTRACT;
    case rhi::BlendOp::ReverseSubtract:
        return VK_BLEND_OP_REVERSE_SUBTRACT;
    case rhi::BlendOp::Min:
        return VK_BLEND_OP_MIN;
    case rhi::BlendOp::Max:
        return VK_BLEND_OP_MAX;
    }
    return VK_BLEND_OP_ADD;
}

VkPipelineColorBlendAttachmentState toVkBlend(const rhi::BlendState& blend) {
    VkPipelineColorBlendAttachmentState state{};
    state.blendEnable = blend.enable;
    state.srcColorBlendFactor = toVkBlendFactor(blend.srcColor);
    state.dstColorBlendFactor = toVkBlendFactor(blend.dstColor);
    state.colorBlendOp = toVkBlendOp(blend.colorOp);
    state.srcAlphaBlendFactor = toVkBlendFactor(blend.srcAlpha);
    state.dstAlphaBlendFactor = toVkBlendFactor(blend.dstAlpha);
    state.alphaBlendOp = toVkBlendOp(blend.alphaOp);
    state.colorWriteMask = blend.writeMask & 0xF; // R, G, B, A bits match VkColorComponentFlagBits
    return state;
}

VkPrimitiveTopology toVkTopology(rhi::PrimitiveTopology topology) {
    switch (topology) {
    case rhi::PrimitiveTopology::TriangleList:
        return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    case rhi::PrimitiveTopology::TriangleStrip:
        return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    case rhi::PrimitiveTopology::LineList:
        return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case rhi::PrimitiveTopology::PointList:
        return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    }
    return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
}

VkCullModeFlags toVkCullMode(rhi::CullMode mode) {
    switch (mode) {
    case rhi::CullMode::None:
        return VK_CULL_MODE_NONE;
    case rhi::CullMode::Front:
        return VK_CULL_MODE_FRONT_BIT;
    case rhi::CullMode::Back:
        return VK_CULL_MODE_BACK_BIT;
    }
    return VK_CULL_MODE_NONE;
}

VkShaderStageFlags graphicsStages(const rhi::GraphicsPipelineDesc& desc) {
    return VK_SHADER_STAGE_VERTEX_BIT | (desc.pixelShader ? VK_SHADER_STAGE_FRAGMENT_BIT : 0);
}

} // namespace

PipelineLayout::PipelineLayout(std::shared_ptr<Context> context,
                               const std::vector<rhi::BindingLayoutHandle>& layouts,
                               uint32_t pushConstantBytes, VkShaderStageFlags stages,
                               const std::string& debugName)
    : context_(std::move(context)), pushConstantBytes_(pushConstantBytes) {
    std::vector<VkDescriptorSetLayout> setLayouts;
    for (size_t space = 0; space < layouts.size(); ++space) {
        const auto* layout = dynamic_cast<const BindingLayout*>(layouts[space].get());
        if (!layout) {
            throw rhi::Error("pipeline '" + debugName + "': layout " + std::to_string(space) +
                             " is missing or not of this backend");
        }
        if (layout->desc().space != space) {
            throw rhi::Error("pipeline '" + debugName +
                             "': layouts are one per register space in order, but " + "entry " +
                             std::to_string(space) + " is for space" + std::to_string(layout->desc().space));
        }
        setLayouts.push_back(layout->handle());
    }
    const uint32_t maxPush = context_->limits().maxPushConstantsSize;
    if (pushConstantBytes % 4 != 0 || pushConstantBytes > maxPush) {
        throw rhi::Error("pipeline '" + debugName + "': " + std::to_string(pushConstantBytes) +
                         " push-constant bytes; must be a multiple of 4 and at most " +
                         std::to_string(maxPush));
    }
    VkPushConstantRange range{stages, 0, pushConstantBytes};
    if (pushConstantBytes > 0) {
        pushConstantStages_ = stages;
    }
    auto info = vkStruct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.setLayoutCount = static_cast<uint32_t>(setLayouts.size());
    info.pSetLayouts = setLayouts.data();
    info.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(context_->device(), &info, nullptr, &layout_), "vkCreatePipelineLayout",
          debugName);
    context_->setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, debugName);
}

PipelineLayout::~PipelineLayout() {
    vkDestroyPipelineLayout(context_->device(), layout_, nullptr);
}

ComputePipeline::ComputePipeline(std::shared_ptr<Context> context, const rhi::ComputePipelineDesc& desc)
    : context_(context), desc_(desc),
      layout_(context, desc.layouts, desc.pushConstantBytes, VK_SHADER_STAGE_COMPUTE_BIT, desc.debugName) {
    const Shader& shader = vulkanShader(desc_.shader, rhi::ShaderStage::Compute, desc_.debugName, "compute");
    auto info = vkStruct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage = stageInfo(shader);
    info.layout = layout_.handle();
    check(vkCreateComputePipelines(context_->device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
          "vkCreateComputePipelines", desc_.debugName + " (kernel " + shader.desc().debugName + ")");
    context_->setName(VK_OBJECT_TYPE_PIPELINE, pipeline_, desc_.debugName);
}

ComputePipeline::~ComputePipeline() {
    vkDestroyPipeline(context_->device(), pipeline_, nullptr);
}

GraphicsPipeline::GraphicsPipeline(std::shared_ptr<Context> context, const rhi::GraphicsPipelineDesc& desc)
    : context_(context), desc_(desc),
      layout_(context, desc.layouts, desc.pushConstantBytes, graphicsStages(desc), desc.debugName) {
    const std::string& name = desc_.debugName;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    stages.push_back(stageInfo(vulkanShader(desc_.vertexShader, rhi::ShaderStage::Vertex, name, "vertex")));
    if (desc_.pixelShader) {
        stages.push_back(stageInfo(vulkanShader(desc_.pixelShader, rhi::ShaderStage::Pixel, name, "pixel")));
    }

    const size_t targets = desc_.colorFormats.size();
    if (!desc_.blend.empty() && desc_.blend.size() != 1 && desc_.blend.size() != targets) {
        throw rhi::Error("pipeline '" + name + "': " + std::to_string(desc_.blend.size()) +
                         " blend states for " + std::to_string(targets) +
                         " colour targets (give 0, 1 or one each)");
    }
    std::vector<VkFormat> colorFormats;
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (size_t target = 0; target < targets; ++target) {
        if (rhi::isDepthFormat(desc_.colorFormats[target])) {
            throw rhi::Error("pipeline '" + name + "': colour target " + std::to_string(target) +
                             " has a depth format");
        }
        colorFormats.push_back(toVkFormat(desc_.colorFormats[target]));
        const rhi::BlendState blend = desc_.blend.empty()       ? rhi::BlendState{}
                                      : desc_.blend.size() == 1 ? desc_.blend[0]
                                                                : desc_.blend[target];
        blends.push_back(toVkBlend(blend));
        if (target > 0 && !context_->features().independentBlend &&
            std::memcmp(&blends[target], &blends[0], sizeof(blends[0])) != 0) {
            throw rhi::Error("pipeline '" + name + "': per-target blend states need independentBlend");
        }
    }
    const bool hasDepth = desc_.depthFormat != rhi::Format::Unknown;
    if (hasDepth && !rhi::isDepthFormat(desc_.depthFormat)) {
        throw rhi::Error("pipeline '" + name + "': depthFormat is not a depth format");
    }

    auto rendering =
        vkStruct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
    rendering.colorAttachmentCount = static_cast<uint32_t>(colorFormats.size());
    rendering.pColorAttachmentFormats = colorFormats.data();
    rendering.depthAttachmentFormat = hasDepth ? toVkFormat(desc_.depthFormat) : VK_FORMAT_UNDEFINED;

    auto vertexInput = vkStruct<VkPipelineVertexInputStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    auto inputAssembly = vkStruct<VkPipelineInputAssemblyStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    inputAssembly.topology = toVkTopology(desc_.topology);

    auto viewport =
        vkStruct<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    const rhi::RasterState& raster = desc_.raster;
    if (!raster.depthClipEnable && !context_->features().depthClamp) {
        throw rhi::Error("pipeline '" + name + "': depthClipEnable = false needs the depthClamp feature");
    }
    if (raster.wireframe && !context_->features().fillModeNonSolid) {
        throw rhi::Error("pipeline '" + name + "': wireframe needs the fillModeNonSolid feature");
    }
    auto rasterization = vkStruct<VkPipelineRasterizationStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    rasterization.depthClampEnable = !raster.depthClipEnable;
    rasterization.polygonMode = raster.wireframe ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
    rasterization.cullMode = toVkCullMode(raster.cullMode);
    // The backend flips the viewport (negative height) so the image matches D3D12's; winding
    // is judged on that image in both APIs, so the flag carries over unchanged.
    rasterization.frontFace =
        raster.frontCounterClockwise ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
    rasterization.depthBiasEnable = raster.depthBias != 0.0f || raster.slopeScaledDepthBias != 0.0f;
    rasterization.depthBiasConstantFactor = raster.depthBias;
    rasterization.depthBiasSlopeFactor = raster.slopeScaledDepthBias;
    rasterization.lineWidth = 1.0f;

    auto multisample = vkStruct<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    auto depth = vkStruct<VkPipelineDepthStencilStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
    depth.depthTestEnable = hasDepth && desc_.depth.testEnable;
    depth.depthWriteEnable = hasDepth && desc_.depth.writeEnable;
    depth.depthCompareOp = toVkCompareOp(desc_.depth.compareOp);
    depth.minDepthBounds = 0.0f;
    depth.maxDepthBounds = 1.0f;

    auto blend = vkStruct<VkPipelineColorBlendStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    blend.attachmentCount = static_cast<uint32_t>(blends.size());
    blend.pAttachments = blends.data();

    const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    auto dynamic =
        vkStruct<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    dynamic.dynamicStateCount = static_cast<uint32_t>(std::size(dynamicStates));
    dynamic.pDynamicStates = dynamicStates;

    auto info = vkStruct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    info.pNext = &rendering;
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &inputAssembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &rasterization;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout_.handle();
    check(vkCreateGraphicsPipelines(context_->device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
          "vkCreateGraphicsPipelines", name);
    context_->setName(VK_OBJECT_TYPE_PIPELINE, pipeline_, name);
}

GraphicsPipeline::~GraphicsPipeline() {
    vkDestroyPipeline(context_->device(), pipeline_, nullptr);
}

} // namespace lumina::vulkan
