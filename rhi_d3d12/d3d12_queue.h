#pragma once
// Queues: one D3D12 command queue and one fence each. Every submission signals the fence with
// the next value, which is what submit() returns and what command lists wait on.
#include "rhi/device.h"
#include "rhi_d3d12/d3d12_context.h"

#include <cstdint>
#include <mutex>
#include <span>

namespace lumina::d3d12 {

D3D12_COMMAND_LIST_TYPE toD3D12(rhi::QueueType type);

// CPU wait until `fence` reaches `value`; a removed device throws rhi::DeviceLostError with
// its report instead of hanging.
void waitForFence(DeviceContext& context, ID3D12Fence* fence, uint64_t value, const char* what);

class Queue final : public rhi::IQueue {
public:
    Queue(ContextHandle context, rhi::QueueType type);
    Queue(const Queue&) = delete;
    Queue& operator=(const Queue&) = delete;

    rhi::QueueType type() const override { return type_; }
    uint64_t submit(std::span<rhi::ICommandList* const> lists) override;
    void waitForQueue(rhi::IQueue& other, uint64_t value) override;
    uint64_t completedValue() override;
    void waitForValue(uint64_t value) override;
    void waitIdle() override;

    ID3D12CommandQueue* native() const { return queue_.Get(); }
    ID3D12Fence* fence() const { return fence_.Get(); }
    uint64_t timestampFrequency() const { return timestampFrequency_; }
    uint64_t lastSubmittedValue();

private:
    ContextHandle context_;
    rhi::QueueType type_;
    ComPtr<ID3D12CommandQueue> queue_;
    ComPtr<ID3D12Fence> fence_;
    uint64_t timestampFrequency_ = 0;
    std::mutex mutex_;
    uint64_t lastSignaled_ = 0;
};

} // namespace lumina::d3d12
