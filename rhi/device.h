#pragma once
// Devices and queues. Backends provide `listAdapters` and `createDevice` functions for their
// API; app/backends.h picks one at run time (--api vulkan|d3d12).
#include "rhi/command_list.h"
#include "rhi/pipeline.h"
#include "rhi/resource.h"
#include "rhi/swapchain.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::rhi {

enum class Api : uint8_t { Vulkan, D3D12 };
std::string_view apiName(Api api);

enum class AdapterType : uint8_t { Discrete, Integrated, Virtual, Cpu, Other };
std::string_view adapterTypeName(AdapterType type);

struct AdapterInfo {
    uint32_t index = 0;
    std::string name;
    std::string driver;     // driver name and version
    std::string apiVersion; // e.g. "1.3.230" or "12_0"
    uint32_t vendorId = 0;
    uint32_t deviceId = 0;
    AdapterType type = AdapterType::Other;
    uint64_t dedicatedMemoryBytes = 0;
};

enum class MessageSeverity : uint8_t { Info, Warning, Error };

struct DeviceDesc {
    uint32_t adapterIndex = 0;
    // Khronos validation layer on Vulkan, the debug layer on D3D12.
    bool validation = false;
    bool synchronizationValidation = false; // Vulkan: VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION
    bool gpuBasedValidation = false;
    // Enables presenting to windows (createSwapchain): the surface and swapchain extensions on
    // Vulkan. Off for headless work, which then needs no window system at all.
    bool presentation = false;
    // Receives every validation warning and error (and the backend's own diagnostics).
    std::function<void(MessageSeverity, std::string_view)> messageCallback;
};

struct DeviceCapabilities {
    ShaderFormat shaderFormat = ShaderFormat::Spirv;
    double timestampPeriodNs = 1.0;
    bool separateComputeQueue = false; // false: the compute queue shares the graphics hardware queue
    uint32_t maxPushConstantBytes = 128;
    uint32_t subgroupSize = 0;
    uint32_t maxTexture2DSize = 0;
    uint32_t maxTexture3DSize = 0;
    // A validation layer checks this device and reports to DeviceDesc::messageCallback: the
    // Khronos layer on Vulkan (requested and missing is an error there), the debug layer with its
    // info queue on D3D12 (absent under Wine, and on Windows without "Graphics Tools").
    bool validationActive = false;
};

class IQueue {
public:
    virtual ~IQueue() = default;
    virtual QueueType type() const = 0;
    // Submits in order; returns the fence value that signals when all of them finished.
    virtual uint64_t submit(std::span<ICommandList* const> lists) = 0;
    uint64_t submit(ICommandList& list) {
        ICommandList* one[] = {&list};
        return submit(one);
    }
    // Makes this queue's later submissions wait on the GPU until `other` reaches `value`.
    virtual void waitForQueue(IQueue& other, uint64_t value) = 0;
    virtual uint64_t completedValue() = 0;
    virtual void waitForValue(uint64_t value) = 0; // CPU wait
    virtual void waitIdle() = 0;
};

class IDevice {
public:
    virtual ~IDevice() = default;

    virtual Api api() const = 0;
    virtual const AdapterInfo& adapter() const = 0;
    virtual const DeviceCapabilities& capabilities() const = 0;

    virtual BufferHandle createBuffer(const BufferDesc& desc) = 0;
    virtual TextureHandle createTexture(const TextureDesc& desc) = 0;
    virtual SamplerHandle createSampler(const SamplerDesc& desc) = 0;
    virtual ShaderHandle createShader(const ShaderDesc& desc, std::span<const uint8_t> bytecode) = 0;
    virtual BindingLayoutHandle createBindingLayout(const BindingLayoutDesc& desc) = 0;
    virtual ComputePipelineHandle createComputePipeline(const ComputePipelineDesc& desc) = 0;
    virtual GraphicsPipelineHandle createGraphicsPipeline(const GraphicsPipelineDesc& desc) = 0;
    virtual CommandListHandle createCommandList(QueueType queue = QueueType::Graphics) = 0;
    // Presents through the graphics queue. Throws rhi::Error when the device was created
    // without DeviceDesc::presentation or the window cannot be presented to.
    virtual SwapchainHandle createSwapchain(const SwapchainDesc& desc) = 0;

    virtual IQueue& queue(QueueType type) = 0;
    virtual void waitIdle() = 0;

    // Validation messages (warnings and errors) received since the device was created.
    virtual uint64_t validationMessageCount() const = 0;
    // Bytes of device memory currently allocated through this device.
    virtual uint64_t allocatedMemoryBytes() const = 0;
};

using DeviceHandle = std::unique_ptr<IDevice>;

} // namespace lumina::rhi
