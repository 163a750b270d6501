#include "rhi_d3d12/d3d12_device.h"

#include "rhi_d3d12/d3d12_adapter.h"
#include "rhi_d3d12/d3d12_backend.h"
#include "rhi_d3d12/d3d12_buffer.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_dred.h"
#include "rhi_d3d12/d3d12_sampler.h"
#include "rhi_d3d12/d3d12_swapchain.h"
#include "rhi_d3d12/d3d12_texture.h"

#include <iterator>
#include <string>

namespace lumina::d3d12 {

namespace {

// Shader-visible heap sizes. 2048 samplers is D3D12's limit for a shader-visible sampler heap;
// 1,000,000 views is resource binding tier 1's for a view heap (976 pages of 1024 stay under it).
// A frame of `city` binds views for thousands of card-capture passes: 65536 did not hold its first
// frame (`RealScenesGpu` on D3D12 under Wine), while identical sampler tables are shared
// (DescriptorTableAllocator::tableOf).
constexpr uint32_t kShaderVisibleViews = 976 * 1024;
constexpr uint32_t kViewPageSize = 1024;
constexpr uint32_t kShaderVisibleSamplers = D3D12_MAX_SHADER_VISIBLE_SAMPLER_HEAP_SIZE;
constexpr uint32_t kSamplerPageSize = 64;

// Messages the debug layer sends about valid code: Lumina creates targets without optimised
// clear values and clears them to whatever the pass needs.
constexpr D3D12_MESSAGE_ID kDeniedMessages[] = {
    D3D12_MESSAGE_ID_CLEARRENDERTARGETVIEW_MISMATCHINGCLEARVALUE,
    D3D12_MESSAGE_ID_CLEARDEPTHSTENCILVIEW_MISMATCHINGCLEARVALUE,
};

} // namespace

Device::Device(const rhi::DeviceDesc& desc) {
    const bool debugLayer = enableDebugLayer(desc);
    std::string dredUnavailable;
    const bool dred = enableDred(dredUnavailable);

    const bool debug = desc.validation || desc.gpuBasedValidation;
    ComPtr<IDXGIFactory4> factory = createFactory(debug);
    std::vector<AdapterEntry> adapters = enumerateAdapters(factory.Get());
    if (desc.adapterIndex >= adapters.size()) {
        throw rhi::Error("D3D12: adapter " + std::to_string(desc.adapterIndex) + " requested, " +
                         std::to_string(adapters.size()) + " adapter(s) support D3D12");
    }
    AdapterEntry& entry = adapters[desc.adapterIndex];
    adapter_ = entry.info;
    ComPtr<ID3D12Device> device;
    check(D3D12CreateDevice(entry.adapter.Get(), kMinimumFeatureLevel, IID_PPV_ARGS(&device)),
          "D3D12CreateDevice('" + adapter_.name + "')");
    setDebugName(device.Get(), "lumina device");
    context_ = std::make_shared<DeviceContext>(device, desc.messageCallback);
    context_->dredEnabled = dred;
    if (!dred) {
        context_->message(rhi::MessageSeverity::Info, "D3D12: DRED unavailable (" + dredUnavailable +
                                                          "); device-removed reports carry the "
                                                          "removal reason only");
    }
    const bool messagesCollected = debugLayer && configureInfoQueue();
    queryCapabilities();
    capabilities_.validationActive = messagesCollected;
    createSharedState();
    roots_ = std::make_unique<RootSignatureCache>(context_);
    pipelines_ = std::make_unique<PipelineCache>(context_, *roots_);
}

Device::~Device() {
    try {
        waitIdle();
    } catch (const std::exception& error) {
        if (context_) {
            context_->message(rhi::MessageSeverity::Error,
                              std::string("D3D12 device destruction: ") + error.what());
        }
    }
}

bool Device::enableDebugLayer(const rhi::DeviceDesc& desc) {
    if (!desc.validation && !desc.gpuBasedValidation) {
        return false;
    }
    const auto report = [&](const std::string& text) {
        if (desc.messageCallback) {
            desc.messageCallback(rhi::MessageSeverity::Info, text);
        }
    };
    ComPtr<ID3D12Debug> debug;
    const HRESULT hr = D3D12GetDebugInterface(IID_PPV_ARGS(&debug));
    if (FAILED(hr)) {
        // Wine's d3d12 has no debug layer, and Windows has none without "Graphics Tools".
        report("D3D12: debug layer unavailable (D3D12GetDebugInterface: " + hresultText(hr) +
               "); running without validation");
        return false;
    }
    debug->EnableDebugLayer();
    if (desc.gpuBasedValidation) {
        ComPtr<ID3D12Debug1> debug1;
        if (SUCCEEDED(debug.As(&debug1))) {
            debug1->SetEnableGPUBasedValidation(TRUE);
        } else {
            report("D3D12: GPU-based validation unavailable (no ID3D12Debug1)");
        }
    }
    return true;
}

bool Device::configureInfoQueue() {
    ComPtr<ID3D12InfoQueue> infoQueue;
    if (FAILED(context_->device()->QueryInterface(IID_PPV_ARGS(&infoQueue)))) {
        context_->message(rhi::MessageSeverity::Info,
                          "D3D12: no info queue; validation messages are not collected");
        return false;
    }
    D3D12_INFO_QUEUE_FILTER filter{};
    filter.DenyList.NumIDs = static_cast<UINT>(std::size(kDeniedMessages));
    filter.DenyList.pIDList = const_cast<D3D12_MESSAGE_ID*>(kDeniedMessages);
    infoQueue->AddStorageFilterEntries(&filter);
    context_->attachInfoQueue(std::move(infoQueue));
    return true;
}

void Device::queryCapabilities() {
    ID3D12Device* device = context_->device();
    context_->highestShaderModel = highestShaderModel(device);
    capabilities_.shaderFormat =
        context_->highestShaderModel >= 0x60 ? rhi::ShaderFormat::Dxil : rhi::ShaderFormat::Dxbc;
    capabilities_.separateComputeQueue = true; // a queue of its own; the driver decides the hardware
    capabilities_.maxPushConstantBytes = kMaxPushConstantBytes;
    capabilities_.maxTexture2DSize = D3D12_REQ_TEXTURE2D_U_OR_V_DIMENSION;
    capabilities_.maxTexture3DSize = D3D12_REQ_TEXTURE3D_U_V_OR_W_DIMENSION;
    D3D12_FEATURE_DATA_D3D12_OPTIONS1 options1{};
    if (SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS1, &options1, sizeof options1)) &&
        options1.WaveOps) {
        capabilities_.subgroupSize = options1.WaveLaneCountMin;
    }
}

void Device::createSharedState() {
    ID3D12Device* device = context_->device();
    shared_ = std::make_shared<CommandListShared>();
    shared_->views = std::make_unique<ShaderVisibleDescriptorHeap>(
        device, D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kShaderVisibleViews, kViewPageSize,
        "lumina shader-visible CBV/SRV/UAV heap");
    shared_->samplers = std::make_unique<ShaderVisibleDescriptorHeap>(
        device, D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER, kShaderVisibleSamplers, kSamplerPageSize,
        "lumina shader-visible sampler heap");

    D3D12_INDIRECT_ARGUMENT_DESC argument{};
    argument.Type = D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH;
    D3D12_COMMAND_SIGNATURE_DESC signature{};
    signature.ByteStride = sizeof(D3D12_DISPATCH_ARGUMENTS);
    signature.NumArgumentDescs = 1;
    signature.pArgumentDescs = &argument;
    check(device->CreateCommandSignature(&signature, nullptr, IID_PPV_ARGS(&shared_->dispatchSignature)),
          "ID3D12Device::CreateCommandSignature(dispatch)", *context_);

    D3D12_FEATURE_DATA_D3D12_OPTIONS3 options3{};
    shared_->copyQueueTimestamps =
        SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS3, &options3, sizeof options3)) &&
        options3.CopyQueueTimestampQueriesSupported;

    for (rhi::QueueType type : {rhi::QueueType::Graphics, rhi::QueueType::Compute, rhi::QueueType::Copy}) {
        queues_[size_t(type)] = std::make_unique<Queue>(context_, type);
        shared_->timestampFrequency[size_t(type)] = queues_[size_t(type)]->timestampFrequency();
    }
    const uint64_t frequency = shared_->timestampFrequency[size_t(rhi::QueueType::Graphics)];
    capabilities_.timestampPeriodNs = frequency ? 1e9 / double(frequency) : 0.0;
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
    return d3d12::createShader(*context_, desc, bytecode);
}

rhi::BindingLayoutHandle Device::createBindingLayout(const rhi::BindingLayoutDesc& desc) {
    auto layout = std::make_shared<BindingLayout>(desc);
    // Build (and cache) the layout's own root signature now, so that a layout D3D12 rejects
    // fails here, where its registers are known, and not at pipeline creation.
    roots_->get({layout}, 0, "binding layout of space " + std::to_string(desc.space));
    return layout;
}

rhi::ComputePipelineHandle Device::createComputePipeline(const rhi::ComputePipelineDesc& desc) {
    return pipelines_->createCompute(desc);
}

rhi::GraphicsPipelineHandle Device::createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) {
    return pipelines_->createGraphics(desc);
}

rhi::CommandListHandle Device::createCommandList(rhi::QueueType queue) {
    static constexpr const char* kNames[] = {"graphics", "compute", "copy"};
    const std::string name = std::string("lumina ") + kNames[size_t(queue)] + " command list " +
                             std::to_string(commandListCount_++);
    return std::make_shared<CommandList>(context_, shared_, queue, name);
}

rhi::SwapchainHandle Device::createSwapchain(const rhi::SwapchainDesc& desc) {
    // DXGI swapchains need no device option: DeviceDesc::presentation matters to Vulkan only.
    return std::make_unique<Swapchain>(context_, *queues_[size_t(rhi::QueueType::Graphics)], desc);
}

rhi::IQueue& Device::queue(rhi::QueueType type) {
    return *queues_.at(size_t(type));
}

void Device::waitIdle() {
    for (auto& queue : queues_) {
        if (queue) {
            queue->waitIdle();
        }
    }
}

rhi::DeviceHandle createDevice(const rhi::DeviceDesc& desc) {
    return std::make_unique<Device>(desc);
}

} // namespace lumina::d3d12
