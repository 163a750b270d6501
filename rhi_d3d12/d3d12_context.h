#pragma once
// What every object of one device shares, and may outlive the rhi::IDevice: the D3D12 device,
// staging descriptor heaps, memory accounting and the message sink. Resources, pipelines and
// command lists hold it by shared_ptr, so destroying them in any order stays safe.
#include "rhi/device.h"
#include "rhi_d3d12/d3d12_descriptor_heap.h"
#include "rhi_d3d12/d3d12_headers.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace lumina::d3d12 {

class DeviceContext {
public:
    DeviceContext(ComPtr<ID3D12Device> device,
                  std::function<void(rhi::MessageSeverity, std::string_view)> callback);
    DeviceContext(const DeviceContext&) = delete;
    DeviceContext& operator=(const DeviceContext&) = delete;

    ID3D12Device* device() const { return device_.Get(); }

    // Committed resource, named, counted in allocatedBytes() until released by the caller
    // through releaseMemory(bytes).
    ComPtr<ID3D12Resource> createCommittedResource(D3D12_HEAP_TYPE heap, const D3D12_RESOURCE_DESC& desc,
                                                   D3D12_RESOURCE_STATES initialState, std::string_view name,
                                                   uint64_t& allocatedBytes);
    ComPtr<ID3D12Resource> createCommittedResource(const D3D12_HEAP_PROPERTIES& heap,
                                                   const D3D12_RESOURCE_DESC& desc,
                                                   D3D12_RESOURCE_STATES initialState, std::string_view name,
                                                   uint64_t& allocatedBytes);
    void releaseMemory(uint64_t bytes) { allocatedBytes_ -= bytes; }
    uint64_t allocatedBytes() const { return allocatedBytes_; }

    StagingDescriptorHeap& stagingViews() { return stagingViews_; }
    StagingDescriptorHeap& stagingSamplers() { return stagingSamplers_; }
    StagingDescriptorHeap& renderTargetViews() { return renderTargetViews_; }
    StagingDescriptorHeap& depthStencilViews() { return depthStencilViews_; }

    // Messages: the backend's own diagnostics and the debug layer's (polled from its info
    // queue). Warnings and errors from the debug layer count as validation messages.
    void message(rhi::MessageSeverity severity, std::string_view text);
    void attachInfoQueue(ComPtr<ID3D12InfoQueue> infoQueue);
    void drainDebugMessages();
    uint64_t validationMessageCount();

    // Highest shader model the runtime and driver accept, as 0x51, 0x60, ..., 0x66.
    uint32_t highestShaderModel = 0x51;
    bool dredEnabled = false;

    // What DRED (and the removal reason) say about a lost device; see d3d12_dred.cpp.
    std::string deviceRemovedReport();
    // Sends the report to the message callback and throws rhi::DeviceLostError.
    [[noreturn]] void throwDeviceLost(std::string_view what);

private:
    ComPtr<ID3D12Device> device_;
    std::function<void(rhi::MessageSeverity, std::string_view)> callback_;
    std::atomic<uint64_t> allocatedBytes_{0};
    std::atomic<uint64_t> validationMessages_{0};
    std::mutex infoQueueMutex_;
    ComPtr<ID3D12InfoQueue> infoQueue_;
    StagingDescriptorHeap stagingViews_;
    StagingDescriptorHeap stagingSamplers_;
    StagingDescriptorHeap renderTargetViews_;
    StagingDescriptorHeap depthStencilViews_;
};

using ContextHandle = std::shared_ptr<DeviceContext>;

} // namespace lumina::d3d12
