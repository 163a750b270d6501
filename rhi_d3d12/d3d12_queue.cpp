#include "rhi_d3d12/d3d12_queue.h"

#include "rhi/fault_injection.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_command_list.h"

#include <string>
#include <vector>

namespace lumina::d3d12 {

namespace {

// How often a CPU wait wakes to ask whether the device was removed.
constexpr DWORD kDeviceCheckIntervalMs = 1000;

} // namespace

D3D12_COMMAND_LIST_TYPE toD3D12(rhi::QueueType type) {
    switch (type) {
    case rhi::QueueType::Graphics:
        return D3D12_COMMAND_LIST_TYPE_DIRECT;
    case rhi::QueueType::Compute:
        return D3D12_COMMAND_LIST_TYPE_COMPUTE;
    case rhi::QueueType::Copy:
        return D3D12_COMMAND_LIST_TYPE_COPY;
    }
    return D3D12_COMMAND_LIST_TYPE_DIRECT;
}

void waitForFence(DeviceContext& context, ID3D12Fence* fence, uint64_t value, const char* what) {
    if (rhi::fault::deviceLost()) {
        context.throwDeviceLost(std::string(what) + " waited for fence value " + std::to_string(value) +
                                rhi::fault::injectedNote());
    }
    if (fence->GetCompletedValue() < value) {
        const HANDLE event = CreateEventW(nullptr, FALSE, FALSE, nullptr);
        if (!event) {
            throw rhi::Error(std::string(what) +
                             ": CreateEvent failed: " + hresultText(HRESULT_FROM_WIN32(GetLastError())));
        }
        const HRESULT hr = fence->SetEventOnCompletion(value, event);
        if (FAILED(hr)) {
            CloseHandle(event);
            check(hr, std::string(what) + ": ID3D12Fence::SetEventOnCompletion", context);
        }
        while (WaitForSingleObject(event, kDeviceCheckIntervalMs) == WAIT_TIMEOUT) {
            if (const HRESULT reason = context.device()->GetDeviceRemovedReason(); FAILED(reason)) {
                CloseHandle(event);
                context.throwDeviceLost(std::string(what) + " waited for fence value " +
                                        std::to_string(value) + " of a device that was removed");
            }
        }
        CloseHandle(event);
    }
    // A removed device completes every fence with UINT64_MAX.
    if (fence->GetCompletedValue() == UINT64_MAX) {
        if (const HRESULT reason = context.device()->GetDeviceRemovedReason(); FAILED(reason)) {
            context.throwDeviceLost(std::string(what) +
                                    ": the fence completed because the device was removed");
        }
    }
    context.drainDebugMessages();
}

Queue::Queue(ContextHandle context, rhi::QueueType type) : context_(std::move(context)), type_(type) {
    D3D12_COMMAND_QUEUE_DESC desc{};
    desc.Type = toD3D12(type);
    desc.Priority = D3D12_COMMAND_QUEUE_PRIORITY_NORMAL;
    ID3D12Device* device = context_->device();
    const std::string name = std::string("lumina ") + rhi::queueTypeName(type) + " queue";
    check(device->CreateCommandQueue(&desc, IID_PPV_ARGS(&queue_)),
          "ID3D12Device::CreateCommandQueue(" + name + ")", *context_);
    setDebugName(queue_.Get(), name);
    check(device->CreateFence(0, D3D12_FENCE_FLAG_NONE, IID_PPV_ARGS(&fence_)),
          "ID3D12Device::CreateFence(" + name + ")", *context_);
    setDebugName(fence_.Get(), name + " fence");
    UINT64 frequency = 0;
    if (SUCCEEDED(queue_->GetTimestampFrequency(&frequency))) {
        timestampFrequency_ = frequency;
    }
}

uint64_t Queue::submit(std::span<rhi::ICommandList* const> lists) {
    std::vector<CommandList*> natives;
    std::vector<ID3D12CommandList*> submitted;
    for (rhi::ICommandList* list : lists) {
        auto* native = dynamic_cast<CommandList*>(list);
        if (!native) {
            throw rhi::Error(std::string("submit to the ") + rhi::queueTypeName(type_) +
                             " queue: a command list is null or from another backend");
        }
        if (native->queueType() != type_) {
            throw rhi::Error(std::string("submit to the ") + rhi::queueTypeName(type_) +
                             " queue: command list '" + native->name() + "' was created for the " +
                             rhi::queueTypeName(native->queueType()) + " queue");
        }
        submitted.push_back(native->prepareSubmit());
        natives.push_back(native);
    }
    std::lock_guard lock(mutex_);
    if (rhi::fault::deviceLostOnSubmit()) {
        // What this queue ran before finishes for real (a blocking wait: no event), so that the
        // teardown after the injected loss destroys nothing in use (rhi/fault_injection.h).
        const uint64_t drained = ++lastSignaled_;
        if (SUCCEEDED(queue_->Signal(fence_.Get(), drained))) {
            fence_->SetEventOnCompletion(drained, nullptr);
        }
        context_->throwDeviceLost(std::string("ID3D12CommandQueue::ExecuteCommandLists on the ") +
                                  rhi::queueTypeName(type_) + " queue" + rhi::fault::injectedNote());
    }
    if (!submitted.empty()) {
        queue_->ExecuteCommandLists(static_cast<UINT>(submitted.size()), submitted.data());
    }
    const uint64_t value = ++lastSignaled_;
    check(queue_->Signal(fence_.Get(), value), "ID3D12CommandQueue::Signal", *context_);
    for (CommandList* native : natives) {
        native->submitted(fence_, value);
    }
    context_->drainDebugMessages();
    return value;
}

void Queue::waitForQueue(rhi::IQueue& other, uint64_t value) {
    auto* native = dynamic_cast<Queue*>(&other);
    if (!native) {
        throw rhi::Error("waitForQueue: the other queue is not a D3D12 queue");
    }
    if (const uint64_t last = native->lastSubmittedValue(); value > last) {
        // The GPU would wait forever.
        throw rhi::Error(std::string("waitForQueue: the ") + rhi::queueTypeName(type_) +
                         " queue would wait for value " + std::to_string(value) + " of the " +
                         rhi::queueTypeName(native->type()) + " queue, which has only " +
                         std::to_string(last) + " submissions");
    }
    check(queue_->Wait(native->fence(), value), "ID3D12CommandQueue::Wait", *context_);
}

uint64_t Queue::lastSubmittedValue() {
    std::lock_guard lock(mutex_);
    return lastSignaled_;
}

uint64_t Queue::completedValue() {
    const uint64_t value = fence_->GetCompletedValue();
    if (rhi::fault::deviceLost()) {
        context_->throwDeviceLost(std::string("completedValue() of the ") + rhi::queueTypeName(type_) +
                                  " queue" + rhi::fault::injectedNote());
    }
    if (value == UINT64_MAX && FAILED(context_->device()->GetDeviceRemovedReason())) {
        context_->throwDeviceLost(std::string("completedValue() of the ") + rhi::queueTypeName(type_) +
                                  " queue");
    }
    return value;
}

void Queue::waitForValue(uint64_t value) {
    {
        std::lock_guard lock(mutex_);
        if (value > lastSignaled_) {
            throw rhi::Error(std::string("waitForValue(") + std::to_string(value) + ") on the " +
                             rhi::queueTypeName(type_) + " queue: only " + std::to_string(lastSignaled_) +
                             " submissions were made");
        }
    }
    waitForFence(*context_, fence_.Get(), value, "waitForValue");
}

void Queue::waitIdle() {
    uint64_t value = 0;
    {
        std::lock_guard lock(mutex_);
        value = ++lastSignaled_;
        check(queue_->Signal(fence_.Get(), value), "ID3D12CommandQueue::Signal", *context_);
    }
    waitForFence(*context_, fence_.Get(), value, "waitIdle");
}

} // namespace lumina::d3d12
