// Command-list lifecycle, barriers, markers, timers and push constants.
#include "rhi_vulkan/vk_command_list.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_pipeline.h"
#include "rhi_vulkan/vk_queue.h"
#include "rhi_vulkan/vk_state.h"
#include "rhi_vulkan/vk_struct.h"
#include "rhi_vulkan/vk_texture.h"

#include <string>

namespace lumina::vulkan {

namespace {

void recordGlobalBarrier(VkCommandBuffer commandBuffer, VkPipelineStageFlags2 dstStages,
                         VkAccessFlags2 dstAccess) {
    auto barrier = vkStruct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = dstStages;
    barrier.dstAccessMask = dstAccess;
    auto dependency = vkStruct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commandBuffer, &dependency);
}

} // namespace

CommandList::CommandList(std::shared_ptr<Context> context, rhi::QueueType type,
                         std::shared_ptr<HardwareQueue> hardware)
    : context_(std::move(context)), type_(type), hardware_(std::move(hardware)), descriptors_(context_),
      upload_(context_, std::string("upload ring of a ") + rhi::queueTypeName(type) + " command list"),
      timestamps_(context_, hardware_->timestampValidBits) {
    auto poolInfo = vkStruct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = hardware_->family;
    check(vkCreateCommandPool(context_->device(), &poolInfo, nullptr, &pool_), "vkCreateCommandPool");

    auto info = vkStruct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    info.commandPool = pool_;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    try {
        check(vkAllocateCommandBuffers(context_->device(), &info, &commandBuffer_),
              "vkAllocateCommandBuffers");
    } catch (...) {
        vkDestroyCommandPool(context_->device(), pool_, nullptr);
        throw;
    }
    context_->setName(VK_OBJECT_TYPE_COMMAND_BUFFER, commandBuffer_,
                      std::string(rhi::queueTypeName(type)) + " command list");
}

CommandList::~CommandList() {
    try {
        waitForSubmission();
    } catch (const rhi::Error&) {
        // Device lost: nothing left to wait for, and destructors must not throw.
    }
    keepAlive_.clear();
    vkDestroyCommandPool(context_->device(), pool_, nullptr);
}

void CommandList::waitForSubmission() {
    if (phase_ != Phase::Submitted) {
        return;
    }
    submittedTo_->waitForValue(submittedValue_);
    previousTimerResults_ = timestamps_.read();
    phase_ = Phase::Ended;
    submittedTo_.reset();
}

void CommandList::releaseRecordingResources() {
    keepAlive_.clear();
    descriptors_.reset();
    upload_.reset();
}

void CommandList::begin() {
    if (phase_ == Phase::Recording) {
        throw rhi::Error(std::string("begin: the ") + rhi::queueTypeName(type_) +
                         " command list is already recording");
    }
    waitForSubmission();
    releaseRecordingResources();
    check(vkResetCommandPool(context_->device(), pool_, 0), "vkResetCommandPool");
    tracker_.reset();
    computeState_.reset();
    graphicsState_.reset();
    pushConstantLayout_ = nullptr;
    rendering_.reset();
    scopes_.clear();

    auto info = vkStruct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commandBuffer_, &info), "vkBeginCommandBuffer");
    phase_ = Phase::Recording;
    timestamps_.reset(commandBuffer_);
    // The tracker knows only what this list wrote: a resource written by an earlier list
    // and used the same way here gets no barrier from it. Like D3D12, which completes and
    // flushes all work between ExecuteCommandLists calls, every list starts by making all
    // earlier writes visible to all of its commands.
    recordGlobalBarrier(commandBuffer_, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

void CommandList::end() {
    requireRecording("end");
    if (!scopes_.empty()) {
        throw rhi::Error("end: " + std::to_string(scopes_.size()) + " markers or timers are still open" +
                         (timestamps_.openRegions()
                              ? ", innermost timer '" + timestamps_.innermostOpenRegion() + "'"
                              : std::string()));
    }
    endRendering();
    recordPendingBarriers();
    // Readback and host-visible buffers are read by the CPU once the queue's fence value
    // signals: make every write available to the host.
    recordGlobalBarrier(commandBuffer_, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    check(vkEndCommandBuffer(commandBuffer_), "vkEndCommandBuffer");
    phase_ = Phase::Ended;
}

void CommandList::checkSubmittable(const Queue& queue) const {
    const std::string where = std::string("submit of a ") + rhi::queueTypeName(type_) +
                              " command list to the " + rhi::queueTypeName(queue.type()) + " queue: ";
    if (phase_ != Phase::Ended) {
        throw rhi::Error(where + (phase_ == Phase::Submitted
                                      ? "already submitted; begin() and record it again"
                                      : "the list has not ended (call end())"));
    }
    if (queue.hardware().family != hardware_->family) {
        throw rhi::Error(where + "the list was recorded for another queue family");
    }
}

void CommandList::markSubmitted(std::shared_ptr<Queue> queue, uint64_t value) {
    phase_ = Phase::Submitted;
    submittedTo_ = std::move(queue);
    submittedValue_ = value;
}

void CommandList::requireRecording(const char* command) const {
    if (phase_ != Phase::Recording) {
        throw rhi::Error(std::string(command) + ": the " + rhi::queueTypeName(type_) +
                         " command list is not recording (call begin())");
    }
}

void CommandList::prepare(const std::function<void()>& requirements, bool staysInRendering) {
    if (automaticBarriers_) {
        try {
            requirements();
        } catch (...) {
            // The tracker has already moved the resources required so far to their new
            // states: record those barriers, so that recorded and tracked states agree.
            recordPendingBarriers();
            finishCommand();
            throw;
        }
    }
    if (!staysInRendering) {
        endRendering();
    }
    // Explicit transitions are recorded before the next command even when barriers are
    // not automatic, so that tracked and recorded states never drift apart.
    recordPendingBarriers();
}

void CommandList::recordPendingBarriers() {
    const std::vector<rhi::Barrier> barriers = tracker_.takeBarriers();
    if (barriers.empty()) {
        return;
    }
    endRendering(); // no barriers inside a render pass instance
    recordBarriers(commandBuffer_, barriers, hardware_->supportsGraphics);
}

void CommandList::requireBindings(const std::vector<rhi::BindingSet>& bindings) {
    for (const rhi::BindingSet& set : bindings) {
        for (const rhi::BindingSetItem& item : set.items) {
            const rhi::ResourceState state = rhi::requiredState(item.type);
            if (item.type == rhi::BindingType::Sampler) {
                continue;
            }
            if (item.texture) {
                require(*item.texture, state);
            } else if (item.buffer) {
                require(*item.buffer, state);
            }
        }
    }
}

void CommandList::keepAlive(std::shared_ptr<const void> object) {
    if (object) {
        keepAlive_.try_emplace(object.get(), std::move(object));
    }
}

Buffer& CommandList::buffer(rhi::IBuffer& buffer, const char* command) {
    auto* vk = dynamic_cast<Buffer*>(&buffer);
    if (!vk) {
        throw rhi::Error(std::string(command) + ": buffer '" + buffer.debugName() +
                         "' is not a Vulkan buffer");
    }
    keepAlive(vk->shared_from_this());
    return *vk;
}

Texture& CommandList::texture(rhi::ITexture& texture, const char* command) {
    auto* vk = dynamic_cast<Texture*>(&texture);
    if (!vk) {
        throw rhi::Error(std::string(command) + ": texture '" + texture.debugName() +
                         "' is not a Vulkan texture");
    }
    keepAlive(vk->shared_from_this());
    return *vk;
}

void CommandList::transition(rhi::IResource& resource, rhi::ResourceState state) {
    requireRecording("transition");
    if (auto* vkBuffer = dynamic_cast<rhi::IBuffer*>(&resource)) {
        buffer(*vkBuffer, "transition");
    } else if (auto* vkTexture = dynamic_cast<rhi::ITexture*>(&resource)) {
        texture(*vkTexture, "transition");
    }
    tracker_.transition(resource, state);
}

void CommandList::uavBarrier(rhi::IResource& resource) {
    requireRecording("uavBarrier");
    tracker_.sameStateBarrier(resource);
}

void CommandList::commitBarriers() {
    requireRecording("commitBarriers");
    recordPendingBarriers();
}

void CommandList::setPushConstants(const void* data, uint32_t size) {
    requireRecording("setPushConstants");
    if (!pushConstantLayout_) {
        throw rhi::Error("setPushConstants: set a compute or graphics state first");
    }
    if (size > pushConstantLayout_->pushConstantBytes() || size % 4 != 0) {
        throw rhi::Error("setPushConstants: " + std::to_string(size) + " bytes, but the pipeline declares " +
                         std::to_string(pushConstantLayout_->pushConstantBytes()) + " (a multiple of 4)");
    }
    vkCmdPushConstants(commandBuffer_, pushConstantLayout_->handle(),
                       pushConstantLayout_->pushConstantStages(), 0, size, data);
}

void CommandList::beginMarker(std::string_view name) {
    requireRecording("beginMarker");
    context_->beginLabel(commandBuffer_, name);
    scopes_.push_back(Scope::Marker);
}

void CommandList::endMarker() {
    requireRecording("endMarker");
    if (scopes_.empty() || scopes_.back() != Scope::Marker) {
        throw rhi::Error(scopes_.empty() ? "endMarker without a matching beginMarker"
                                         : "endMarker while timer '" + timestamps_.innermostOpenRegion() +
                                               "' is open inside the marker");
    }
    context_->endLabel(commandBuffer_);
    scopes_.pop_back();
}

void CommandList::beginTimer(std::string_view name) {
    requireRecording("beginTimer");
    if (timestamps_.nextNeedsCommandReset()) {
        endRendering();
    }
    context_->beginLabel(commandBuffer_, name);
    if (context_->timestampsNeedBarrier()) {
        endRendering(); // draws before the timestamp are rasterised before it
    }
    timestamps_.beginRegion(commandBuffer_, name);
    barrierAfterTimestamp();
    scopes_.push_back(Scope::Timer);
}

void CommandList::endTimer() {
    requireRecording("endTimer");
    if (scopes_.empty() || scopes_.back() != Scope::Timer) {
        throw rhi::Error(timestamps_.openRegions() == 0 ? "endTimer without a matching beginTimer"
                                                        : "endTimer while a marker is open inside timer '" +
                                                              timestamps_.innermostOpenRegion() + "'");
    }
    if (timestamps_.nextNeedsCommandReset()) {
        endRendering();
    }
    if (context_->timestampsNeedBarrier()) {
        endRendering();
    }
    timestamps_.endRegion(commandBuffer_);
    barrierAfterTimestamp();
    context_->endLabel(commandBuffer_);
    scopes_.pop_back();
}

void CommandList::barrierAfterTimestamp() {
    if (!context_->timestampsNeedBarrier()) {
        return;
    }
    // Execution only, no access scopes: it orders, but makes no write visible, so synchronization
    // validation still reports a missing read-after-write or write-after-write barrier. The
    // callers ended any rendering: a barrier inside it would need a self-dependency.
    auto barrier = vkStruct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    auto dependency = vkStruct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commandBuffer_, &dependency);
}

std::vector<rhi::TimerResult> CommandList::timerResults() {
    if (phase_ != Phase::Submitted) {
        return previousTimerResults_;
    }
    if (submittedTo_->completedValue() < submittedValue_) {
        throw rhi::Error(std::string("timerResults: the ") + rhi::queueTypeName(type_) +
                         " command list's submission has not finished; wait for value " +
                         std::to_string(submittedValue_) + " of its queue first");
    }
    return timestamps_.read();
}

} // namespace lumina::vulkan
