#include "rhi_d3d12/d3d12_context.h"

#include "rhi_d3d12/d3d12_check.h"

#include <vector>

namespace lumina::d3d12 {

namespace {
// Descriptors per CPU-only heap; heaps are added as views are created.
constexpr uint32_t kStagingViewsPerHeap = 4096;
constexpr uint32_t kStagingSamplersPerHeap = 256;
constexpr uint32_t kTargetViewsPerHeap = 256;
} // namespace

DeviceContext::DeviceContext(ComPtr<ID3D12Device> device,
                             std::function<void(rhi::MessageSeverity, std::string_view)> callback)
    : device_(std::move(device)), callback_(std::move(callback)),
      stagingViews_(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kStagingViewsPerHeap,
                    "lumina staging CBV/SRV/UAV heap"),
      stagingSamplers_(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER, kStagingSamplersPerHeap,
                       "lumina staging sampler heap"),
      renderTargetViews_(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_RTV, kTargetViewsPerHeap,
                         "lumina RTV heap"),
      depthStencilViews_(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_DSV, kTargetViewsPerHeap,
                         "lumina DSV heap") {}

ComPtr<ID3D12Resource> DeviceContext::createCommittedResource(D3D12_HEAP_TYPE heap,
                                                              const D3D12_RESOURCE_DESC& desc,
                                                              D3D12_RESOURCE_STATES initialState,
                                                              std::string_view name,
                                                              uint64_t& allocatedBytes) {
    D3D12_HEAP_PROPERTIES properties{};
    properties.Type = heap;
    return createCommittedResource(properties, desc, initialState, name, allocatedBytes);
}

ComPtr<ID3D12Resource> DeviceContext::createCommittedResource(const D3D12_HEAP_PROPERTIES& properties,
                                                              const D3D12_RESOURCE_DESC& desc,
                                                              D3D12_RESOURCE_STATES initialState,
                                                              std::string_view name,
                                                              uint64_t& allocatedBytes) {
    ComPtr<ID3D12Resource> resource;
    check(device_->CreateCommittedResource(&properties, D3D12_HEAP_FLAG_NONE, &desc, initialState, nullptr,
                                           IID_PPV_ARGS(&resource)),
          "ID3D12Device::CreateCommittedResource('" + std::string(name) + "')", *this);
    setDebugName(resource.Get(), name);
    const D3D12_RESOURCE_ALLOCATION_INFO info = allocationInfo(device_.Get(), desc);
    allocatedBytes = info.SizeInBytes;
    allocatedBytes_ += allocatedBytes;
    return resource;
}

void DeviceContext::message(rhi::MessageSeverity severity, std::string_view text) {
    if (callback_) {
        callback_(severity, text);
    }
}

void DeviceContext::attachInfoQueue(ComPtr<ID3D12InfoQueue> infoQueue) {
    std::lock_guard lock(infoQueueMutex_);
    infoQueue_ = std::move(infoQueue);
}

void DeviceContext::drainDebugMessages() {
    std::lock_guard lock(infoQueueMutex_);
    if (!infoQueue_) {
        return;
    }
    const UINT64 count = infoQueue_->GetNumStoredMessagesAllowedByRetrievalFilter();
    for (UINT64 i = 0; i < count; ++i) {
        SIZE_T length = 0;
        if (FAILED(infoQueue_->GetMessage(i, nullptr, &length)) || length == 0) {
            continue;
        }
        std::vector<char> storage(length);
        auto* entry = reinterpret_cast<D3D12_MESSAGE*>(storage.data());
        if (FAILED(infoQueue_->GetMessage(i, entry, &length))) {
            continue;
        }
        rhi::MessageSeverity severity = rhi::MessageSeverity::Info;
        if (entry->Severity == D3D12_MESSAGE_SEVERITY_CORRUPTION ||
            entry->Severity == D3D12_MESSAGE_SEVERITY_ERROR) {
            severity = rhi::MessageSeverity::Error;
        } else if (entry->Severity == D3D12_MESSAGE_SEVERITY_WARNING) {
            severity = rhi::MessageSeverity::Warning;
        }
        if (severity != rhi::MessageSeverity::Info) {
            ++validationMessages_;
        }
        message(severity,
                std::string("D3D12 [id ") + std::to_string(int(entry->ID)) + "] " +
                    std::string(entry->pDescription,
                                entry->DescriptionByteLength ? entry->DescriptionByteLength - 1 : 0));
    }
    infoQueue_->ClearStoredMessages();
}

uint64_t DeviceContext::validationMessageCount() {
    drainDebugMessages();
    return validationMessages_;
}

void DeviceContext::throwDeviceLost(std::string_view what) {
    const std::string report = "D3D12 device lost: " + std::string(what) + "\n" + deviceRemovedReport();
    message(rhi::MessageSeverity::Error, report);
    throw rhi::DeviceLostError(report);
}

} // namespace lumina::d3d12
