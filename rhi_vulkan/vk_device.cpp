#include "rhi_vulkan/vk_device.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_binding.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_command_list.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_pipeline.h"
#include "rhi_vulkan/vk_queue.h"
#include "rhi_vulkan/vk_sampler.h"
#include "rhi_vulkan/vk_shader.h"
#include "rhi_vulkan/vk_swapchain.h"
#include "rhi_vulkan/vk_texture.h"

namespace lumina::vulkan {

namespace {
size_t queueIndex(rhi::QueueType type) {
    return static_cast<size_t>(type);
}
} // namespace

Device::Device(const rhi::DeviceDesc& desc) : context_(std::make_shared<Context>(desc)) {
    const VkPhysicalDeviceLimits& limits = context_->limits();
    capabilities_.shaderFormat = rhi::ShaderFormat::Spirv;
    capabilities_.timestampPeriodNs = limits.timestampPeriod;
    capabilities_.separateComputeQueue = context_->computeQueue() != context_->graphicsQueue();
    capabilities_.maxPushConstantBytes = limits.maxPushConstantsSize;
    capabilities_.subgroupSize = context_->subgroupSize();
    capabilities_.maxTexture2DSize = limits.maxImageDimension2D;
    capabilities_.maxTexture3DSize = limits.maxImageDimension3D;
    // The instance throws when validation is requested and the layer is missing.
    capabilities_.validationActive =
        desc.validation || desc.synchronizationValidation || desc.gpuBasedValidation;

    queues_[queueIndex(rhi::QueueType::Graphics)] =
        std::make_shared<Queue>(context_, rhi::QueueType::Graphics, context_->graphicsQueue());
    queues_[queueIndex(rhi::QueueType::Compute)] =
        std::make_shared<Queue>(context_, rhi::QueueType::Compute, context_->computeQueue());
    queues_[queueIndex(rhi::QueueType::Copy)] =
        std::make_shared<Queue>(context_, rhi::QueueType::Copy, context_->graphicsQueue());
}

Device::~Device() {
    try {
        waitIdle();
    } catch (const rhi::Error&) {
        // Device lost: the context still releases what it can.
    }
}

const rhi::AdapterInfo& Device::adapter() const {
    return context_->adapter();
}

rhi::BufferHandle Device::createBuffer(const rhi::BufferDesc& desc) {
    return std::make_shared<Buffer>(context_, desc);
}

rhi::TextureHandle Device::createTexture(const rhi::TextureDesc& desc) {
    return std::make_shared<Texture>(context_, desc);
}

rhi::SamplerHandle Device::createSampler(const rhi::SamplerDesc& desc) {
    return std::make_shared<Sampler>(context_, desc);
}

rhi::ShaderHandle Device::createShader(const rhi::ShaderDesc& desc, std::span<const uint8_t> bytecode) {
    return std::make_shared<Shader>(context_, desc, bytecode);
}

rhi::BindingLayoutHandle Device::createBindingLayout(const rhi::BindingLayoutDesc& desc) {
    return std::make_shared<BindingLayout>(context_, desc);
}

rhi::ComputePipelineHandle Device::createComputePipeline(const rhi::ComputePipelineDesc& desc) {
    return std::make_shared<ComputePipeline>(context_, desc);
}

rhi::GraphicsPipelineHandle Device::createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) {
    return std::make_shared<GraphicsPipeline>(context_, desc);
}

rhi::CommandListHandle Device::createCommandList(rhi::QueueType queue) {
    const auto& hardware =
        queue == rhi::QueueType::Compute ? context_->computeQueue() : context_->graphicsQueue();
    return std::make_shared<CommandList>(context_, queue, hardware);
}

rhi::IQueue& Device::queue(rhi::QueueType type) {
    const size_t index = queueIndex(type);
    if (index >= std::size(queues_)) {
        throw rhi::Error("queue: invalid queue type " + std::to_string(index));
    }
    return *queues_[index];
}

void Device::waitIdle() {
    for (const auto& queue : queues_) {
        queue->waitIdle();
    }
}

uint64_t Device::validationMessageCount() const {
    return context_->messageCount();
}

uint64_t Device::allocatedMemoryBytes() const {
    return context_->allocatedBytes();
}

rhi::SwapchainHandle Device::createSwapchain(const rhi::SwapchainDesc& desc) {
    return std::make_unique<Swapchain>(context_, desc);
}

} // namespace lumina::vulkan
