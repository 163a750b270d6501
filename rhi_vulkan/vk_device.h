#pragma once
#include "rhi/device.h"

#include <memory>

namespace lumina::vulkan {

class Context;
class Queue;

class Device final : public rhi::IDevice {
public:
    explicit Device(const rhi::DeviceDesc& desc);
    ~Device() override;
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    rhi::Api api() const override { return rhi::Api::Vulkan; }
    const rhi::AdapterInfo& adapter() const override;
    const rhi::DeviceCapabilities& capabilities() const override { return capabilities_; }

    rhi::BufferHandle createBuffer(const rhi::BufferDesc& desc) override;
    rhi::TextureHandle createTexture(const rhi::TextureDesc& desc) override;
    rhi::SamplerHandle createSampler(const rhi::SamplerDesc& desc) override;
    rhi::ShaderHandle createShader(const rhi::ShaderDesc& desc, std::span<const uint8_t> bytecode) override;
    rhi::BindingLayoutHandle createBindingLayout(const rhi::BindingLayoutDesc& desc) override;
    rhi::ComputePipelineHandle createComputePipeline(const rhi::ComputePipelineDesc& desc) override;
    rhi::GraphicsPipelineHandle createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) override;
    rhi::CommandListHandle createCommandList(rhi::QueueType queue) override;
    rhi::SwapchainHandle createSwapchain(const rhi::SwapchainDesc& desc) override;

    rhi::IQueue& queue(rhi::QueueType type) override;
    void waitIdle() override;

    uint64_t validationMessageCount() const override;
    uint64_t allocatedMemoryBytes() const override;

private:
    std::shared_ptr<Context> context_;
    rhi::DeviceCapabilities capabilities_;
    // Graphics, compute, copy. Copy shares the graphics VkQueue (no transfer-only family is
    // used yet); compute gets its own VkQueue when the device has one.
    std::shared_ptr<Queue> queues_[3];
};

} // namespace lumina::vulkan
