#pragma once
// An rhi queue: a VkQueue (possibly shared with another rhi queue) and a timeline
// semaphore of its own, whose value counts this queue's submissions.
#include "rhi/device.h"

#include <memory>
#include <mutex>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;
struct HardwareQueue;

class Queue final : public rhi::IQueue, public std::enable_shared_from_this<Queue> {
public:
    Queue(std::shared_ptr<Context> context, rhi::QueueType type, std::shared_ptr<HardwareQueue> hardware);
    ~Queue() override;
    Queue(const Queue&) = delete;
    Queue& operator=(const Queue&) = delete;

    rhi::QueueType type() const override { return type_; }
    uint64_t submit(std::span<rhi::ICommandList* const> lists) override;
    void waitForQueue(rhi::IQueue& other, uint64_t value) override;
    uint64_t completedValue() override;
    void waitForValue(uint64_t value) override;
    void waitIdle() override;

    const HardwareQueue& hardware() const { return *hardware_; }
    VkSemaphore timeline() const { return timeline_; }
    uint64_t lastSubmittedValue() const;

private:
    std::shared_ptr<Context> context_;
    rhi::QueueType type_;
    std::shared_ptr<HardwareQueue> hardware_;
    VkSemaphore timeline_ = VK_NULL_HANDLE;

    mutable std::mutex mutex_;
    uint64_t lastSubmitted_ = 0;
    std::vector<VkSemaphoreSubmitInfo> pendingWaits_; // for the next submit
};

} // namespace lumina::vulkan
