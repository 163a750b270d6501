#pragma once
// The D3D12 device: creation (debug layer, GPU-based validation and DRED), capabilities, the
// factories of every RHI object, and the three queues.
#include "rhi/device.h"
#include "rhi_d3d12/d3d12_binding.h"
#include "rhi_d3d12/d3d12_command_list.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_pipeline.h"
#include "rhi_d3d12/d3d12_queue.h"

#include <array>
#include <atomic>
#include <memory>

namespace lumina::d3d12 {

class Device final : public rhi::IDevice {
public:
    explicit Device(const rhi::DeviceDesc& desc);
    ~Device() override;

    rhi::Api api() const override { return rhi::Api::D3D12; }
    const rhi::AdapterInfo& adapter() const override { return adapter_; }
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

    uint64_t validationMessageCount() const override { return context_->validationMessageCount(); }
    uint64_t allocatedMemoryBytes() const override { return context_->allocatedBytes(); }

private:
    // False when validation was asked for and the debug layer is not installed.
    bool enableDebugLayer(const rhi::DeviceDesc& desc);
    // False when the device has no info queue (messages then cannot be collected).
    bool configureInfoQueue();
    void queryCapabilities();
    void createSharedState();

    ContextHandle context_;
    rhi::AdapterInfo adapter_;
    rhi::DeviceCapabilities capabilities_;
    std::shared_ptr<CommandListShared> shared_;
    std::unique_ptr<RootSignatureCache> roots_;
    std::unique_ptr<PipelineCache> pipelines_;
    std::array<std::unique_ptr<Queue>, 3> queues_;
    std::atomic<uint32_t> commandListCount_{0};
};

} // namespace lumina::d3d12
