#pragma once
// Command recording into one VkCommandBuffer. Every command asks the shared
// rhi::StateTracker for the states its resources must be in, records the barriers that
// answers with, then the command. Graphics work runs in dynamic-rendering instances begun
// lazily by draws and ended by anything that may not run inside one (barriers included).
//
// Lifetime: everything a recording uses (resources, pipelines, descriptor sets, upload
// memory, query pools) stays alive until the next begin(), which first waits for the
// previous submission to finish. Destroying a submitted list waits as well.
#include "rhi/command_list.h"
#include "rhi/state_tracker.h"
#include "rhi_vulkan/vk_descriptor_allocator.h"
#include "rhi_vulkan/vk_timestamp_queries.h"
#include "rhi_vulkan/vk_upload_ring.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Buffer;
class Context;
class PipelineLayout;
class Queue;
class Texture;
struct HardwareQueue;

class CommandList final : public rhi::ICommandList {
public:
    CommandList(std::shared_ptr<Context> context, rhi::QueueType type,
                std::shared_ptr<HardwareQueue> hardware);
    ~CommandList() override;
    CommandList(const CommandList&) = delete;
    CommandList& operator=(const CommandList&) = delete;

    rhi::QueueType queueType() const override { return type_; }
    void begin() override;
    void end() override;

    void setAutomaticBarriers(bool enabled) override { automaticBarriers_ = enabled; }
    void transition(rhi::IResource& resource, rhi::ResourceState state) override;
    void uavBarrier(rhi::IResource& resource) override;
    void commitBarriers() override;

    void copyBuffer(rhi::IBuffer& dst, uint64_t dstOffset, rhi::IBuffer& src, uint64_t srcOffset,
                    uint64_t size) override;
    void copyBufferToTexture(rhi::ITexture& dst, rhi::TextureSlice slice, rhi::IBuffer& src,
                             uint64_t srcOffset, uint32_t rowPitch) override;
    void copyTextureToBuffer(rhi::IBuffer& dst, uint64_t dstOffset, uint32_t rowPitch, rhi::ITexture& src,
                             rhi::TextureSlice slice) override;
    void copyTexture(rhi::ITexture& dst, rhi::TextureSlice dstSlice, rhi::ITexture& src,
                     rhi::TextureSlice srcSlice) override;
    void writeBuffer(rhi::IBuffer& dst, const void* data, uint64_t size, uint64_t dstOffset) override;
    void writeTexture(rhi::ITexture& dst, rhi::TextureSlice slice, const void* data) override;
    void fillBuffer(rhi::IBuffer& dst, uint32_t value) override;
    void clearColor(rhi::ITexture& texture, std::array<float, 4> value) override;
    void clearColorUint(rhi::ITexture& texture, std::array<uint32_t, 4> value) override;
    void clearDepth(rhi::ITexture& texture, float depth) override;

    void setComputeState(const rhi::ComputeState& state) override;
    void setPushConstants(const void* data, uint32_t size) override;
    void dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) override;
    void dispatchIndirect(rhi::IBuffer& args, uint64_t offset) override;

    void setGraphicsState(const rhi::GraphicsState& state) override;
    void draw(const rhi::DrawArgs& args) override;
    void drawIndexed(const rhi::DrawArgs& args) override;

    void beginMarker(std::string_view name) override;
    void endMarker() override;
    void beginTimer(std::string_view name) override;
    void endTimer() override;
    std::vector<rhi::TimerResult> timerResults() override;

    // --- for Queue::submit ----------------------------------------------------------
    VkCommandBuffer handle() const { return commandBuffer_; }
    // Throws unless the list has ended and `queue` runs its queue family.
    void checkSubmittable(const Queue& queue) const;
    void markSubmitted(std::shared_ptr<Queue> queue, uint64_t value);

private:
    enum class Phase { Initial, Recording, Ended, Submitted };
    enum class Scope { Marker, Timer };

    // Commands (vk_command_list.cpp)
    void requireRecording(const char* command) const;
    // Runs `requirements` (tracker_.require calls) when barriers are automatic, then records
    // the barriers pending. `staysInRendering`: draws may continue an active render pass;
    // everything else ends it first.
    void prepare(const std::function<void()>& requirements, bool staysInRendering = false);
    void recordPendingBarriers();
    void require(rhi::IResource& resource, rhi::ResourceState state) { tracker_.require(resource, state); }
    void requireBindings(const std::vector<rhi::BindingSet>& bindings);
    void finishCommand() { tracker_.commandRecorded(); }
    void keepAlive(std::shared_ptr<const void> object);
    Buffer& buffer(rhi::IBuffer& buffer, const char* command);
    Texture& texture(rhi::ITexture& texture, const char* command);
    void waitForSubmission();
    void releaseRecordingResources();

    // Compute and graphics (vk_command_list_draw.cpp)
    std::vector<VkDescriptorSet> writeBindings(const std::vector<rhi::BindingSet>& bindings,
                                               const std::vector<rhi::BindingLayoutHandle>& layouts,
                                               const std::string& pipelineName);
    void prepareDraw(const char* command, bool indexed);
    void beginRendering();
    void endRendering();
    // See Context::timestampsNeedBarrier.
    void barrierAfterTimestamp();

    std::shared_ptr<Context> context_;
    rhi::QueueType type_;
    std::shared_ptr<HardwareQueue> hardware_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    Phase phase_ = Phase::Initial;
    std::shared_ptr<Queue> submittedTo_;
    uint64_t submittedValue_ = 0;

    rhi::StateTracker tracker_;
    bool automaticBarriers_ = true;
    std::unordered_map<const void*, std::shared_ptr<const void>> keepAlive_;
    DescriptorAllocator descriptors_;
    UploadRing upload_;
    TimestampQueries timestamps_;
    std::vector<rhi::TimerResult> previousTimerResults_;
    std::vector<Scope> scopes_; // open markers and timers, innermost last

    // Bound state.
    std::optional<rhi::ComputeState> computeState_;
    std::optional<rhi::GraphicsState> graphicsState_;
    const PipelineLayout* pushConstantLayout_ = nullptr; // of the last set*State

    // The active dynamic-rendering instance, if any, and the attachments it was begun with.
    struct AttachmentKey {
        const rhi::ITexture* texture = nullptr;
        uint32_t mip = 0;
        uint32_t layer = 0;
        bool operator==(const AttachmentKey&) const = default;
    };
    struct RenderingKey {
        std::vector<AttachmentKey> colors;
        std::optional<AttachmentKey> depth;
        bool depthReadOnly = false;
        bool operator==(const RenderingKey&) const = default;
    };
    std::optional<RenderingKey> rendering_;
    RenderingKey renderingKeyOf(const rhi::GraphicsState& state) const;
};

} // namespace lumina::vulkan
