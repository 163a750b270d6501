#include "rhi_vulkan/vk_queue.h"

#include "rhi/error.h"
#include "rhi/fault_injection.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_command_list.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <string>

namespace lumina::vulkan {

namespace {

// A lost device's work ends in finite time and its objects may then be destroyed; an injected
// loss (rhi/fault_injection.h) lets the driver finish what was submitted before, for real, so
// that the teardown after it destroys nothing still in use.
void finishForInjectedLoss(Context& context) {
    for (const auto& hardware : {context.graphicsQueue(), context.computeQueue()}) {
        std::lock_guard hardwareLock(hardware->submitMutex);
        vkQueueWaitIdle(hardware->queue);
    }
}

} // namespace

Queue::Queue(std::shared_ptr<Context> context, rhi::QueueType type, std::shared_ptr<HardwareQueue> hardware)
    : context_(std::move(context)), type_(type), hardware_(std::move(hardware)) {
    auto timelineInfo = vkStruct<VkSemaphoreTypeCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO);
    timelineInfo.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    timelineInfo.initialValue = 0;
    auto info = vkStruct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    info.pNext = &timelineInfo;
    const std::string name = std::string(rhi::queueTypeName(type_)) + " queue timeline";
    check(vkCreateSemaphore(context_->device(), &info, nullptr, &timeline_), "vkCreateSemaphore", name);
    context_->setName(VK_OBJECT_TYPE_SEMAPHORE, timeline_, name);
}

Queue::~Queue() {
    try {
        waitIdle();
    } catch (const rhi::Error&) {
        // Device lost: nothing left to wait for.
    }
    vkDestroySemaphore(context_->device(), timeline_, nullptr);
}

uint64_t Queue::submit(std::span<rhi::ICommandList* const> lists) {
    std::vector<CommandList*> vkLists;
    std::vector<VkCommandBufferSubmitInfo> buffers;
    for (rhi::ICommandList* list : lists) {
        auto* vkList = dynamic_cast<CommandList*>(list);
        if (!vkList) {
            throw rhi::Error(std::string("submit to the ") + rhi::queueTypeName(type_) +
                             " queue: a command list of another backend");
        }
        vkList->checkSubmittable(*this);
        vkLists.push_back(vkList);
        auto buffer = vkStruct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
        buffer.commandBuffer = vkList->handle();
        buffers.push_back(buffer);
    }

    std::lock_guard lock(mutex_);
    const uint64_t value = lastSubmitted_ + 1;
    auto signal = vkStruct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    signal.semaphore = timeline_;
    signal.value = value;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    auto submit = vkStruct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submit.waitSemaphoreInfoCount = static_cast<uint32_t>(pendingWaits_.size());
    submit.pWaitSemaphoreInfos = pendingWaits_.data();
    submit.commandBufferInfoCount = static_cast<uint32_t>(buffers.size());
    submit.pCommandBufferInfos = buffers.data();
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    const std::string what =
        std::string(rhi::queueTypeName(type_)) + " queue, value " + std::to_string(value);
    if (rhi::fault::deviceLostOnSubmit()) {
        finishForInjectedLoss(*context_);
        check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit2", what + rhi::fault::injectedNote());
    }
    {
        std::lock_guard hardwareLock(hardware_->submitMutex);
        check(vkQueueSubmit2(hardware_->queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit2", what);
    }
    lastSubmitted_ = value;
    pendingWaits_.clear();
    for (CommandList* list : vkLists) {
        list->markSubmitted(shared_from_this(), value);
    }
    return value;
}

void Queue::waitForQueue(rhi::IQueue& other, uint64_t value) {
    auto* vkOther = dynamic_cast<Queue*>(&other);
    if (!vkOther) {
        throw rhi::Error("waitForQueue: the other queue is of another backend");
    }
    if (vkOther == this) {
        return; // a queue's own submissions already run in order
    }
    if (value > vkOther->lastSubmittedValue()) {
        // On a shared VkQueue this wait could never be satisfied: it would deadlock.
        throw rhi::Error(std::string("waitForQueue: the ") + rhi::queueTypeName(type_) +
                         " queue would wait for value " + std::to_string(value) + " of the " +
                         rhi::queueTypeName(other.type()) + " queue, which has submitted only " +
                         std::to_string(vkOther->lastSubmittedValue()));
    }
    auto wait = vkStruct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    wait.semaphore = vkOther->timeline();
    wait.value = value;
    // Everything after the wait depends on it: the semaphore's memory dependency then makes
    // the other queue's writes visible to all of this queue's later commands.
    wait.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    std::lock_guard lock(mutex_);
    pendingWaits_.push_back(wait);
}

uint64_t Queue::completedValue() {
    uint64_t value = 0;
    if (rhi::fault::deviceLost()) {
        check(VK_ERROR_DEVICE_LOST, "vkGetSemaphoreCounterValue",
              std::string(rhi::queueTypeName(type_)) + " queue" + rhi::fault::injectedNote());
    }
    check(vkGetSemaphoreCounterValue(context_->device(), timeline_, &value), "vkGetSemaphoreCounterValue",
          std::string(rhi::queueTypeName(type_)) + " queue");
    return value;
}

void Queue::waitForValue(uint64_t value) {
    const uint64_t submitted = lastSubmittedValue();
    if (value > submitted) {
        throw rhi::Error(std::string("waitForValue: the ") + rhi::queueTypeName(type_) +
                         " queue has submitted only " + std::to_string(submitted) + ", waiting for " +
                         std::to_string(value) + " would never return");
    }
    if (rhi::fault::deviceLost()) {
        check(VK_ERROR_DEVICE_LOST, "vkWaitSemaphores",
              std::string(rhi::queueTypeName(type_)) + " queue, value " + std::to_string(value) +
                  rhi::fault::injectedNote());
    }
    auto info = vkStruct<VkSemaphoreWaitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO);
    info.semaphoreCount = 1;
    info.pSemaphores = &timeline_;
    info.pValues = &value;
    check(vkWaitSemaphores(context_->device(), &info, UINT64_MAX), "vkWaitSemaphores",
          std::string(rhi::queueTypeName(type_)) + " queue, value " + std::to_string(value));
}

void Queue::waitIdle() {
    waitForValue(lastSubmittedValue());
}

uint64_t Queue::lastSubmittedValue() const {
    std::lock_guard lock(mutex_);
    return lastSubmitted_;
}

} // namespace lumina::vulkan
