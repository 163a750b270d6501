#pragma once
// Command lists. Each owns a command allocator, a graphics command list, its upload memory,
// descriptor-table cursors into the shader-visible heaps and its timestamp queries. Barriers
// come from the shared rhi::StateTracker: before every copy, clear, dispatch and draw the
// list asks the tracker for the states that command needs and records what it answers
// (transitions, UAV barriers between writes). Everything a recording uses is kept alive
// until the next begin(), which first waits for the previous submission.
//
// Recording is split by concern: this file's .cpp holds the lifecycle, barriers, markers and
// timers; d3d12_command_list_copy.cpp the copies, uploads and clears;
// d3d12_command_list_draw.cpp compute and graphics state, dispatches and draws.
#include "rhi/command_list.h"
#include "rhi/state_tracker.h"
#include "rhi_d3d12/d3d12_binding.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_descriptor_heap.h"
#include "rhi_d3d12/d3d12_state.h"
#include "rhi_d3d12/d3d12_timer.h"
#include "rhi_d3d12/d3d12_upload.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace lumina::d3d12 {

class Buffer;
class Texture;
class ComputePipeline;
class GraphicsPipeline;

// What every list of a device shares besides the DeviceContext: the shader-visible heaps,
// the command signature of indirect dispatches and the queues' timestamp frequencies.
struct CommandListShared {
    std::unique_ptr<ShaderVisibleDescriptorHeap> views;
    std::unique_ptr<ShaderVisibleDescriptorHeap> samplers;
    ComPtr<ID3D12CommandSignature> dispatchSignature;
    std::array<uint64_t, 3> timestampFrequency{}; // ticks per second, by rhi::QueueType
    bool copyQueueTimestamps = false;
};

class CommandList final : public rhi::ICommandList {
public:
    CommandList(ContextHandle context, std::shared_ptr<CommandListShared> shared, rhi::QueueType type,
                std::string name);
    ~CommandList() override;

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

    // For Queue::submit.
    const std::string& name() const { return name_; }
    ID3D12CommandList* prepareSubmit();
    void submitted(const ComPtr<ID3D12Fence>& fence, uint64_t value);

private:
    enum class Recording : uint8_t { Initial, Open, Closed, Submitted };

    void requireOpen(const char* command) const;
    void requireQueue(const char* command, bool graphicsOnly) const;
    // The next command uses `resource` in `state`: asks the tracker (with automatic barriers)
    // and keeps the resource alive for this recording.
    void use(rhi::IResource& resource, rhi::ResourceState state);
    // Records the barriers the tracker answered, and the pixel-shader-read upgrades of
    // resources last transitioned on a compute list.
    void flushBarriers();
    // After recording a command: the tracker learns which resources it wrote.
    void commandRecorded();
    void keepAlive(NativeResource& resource);
    void transitionNative(NativeResource& resource, D3D12_RESOURCE_STATES state,
                          std::vector<D3D12_RESOURCE_BARRIER>& barriers);
    bool finished();
    void beginEvent(std::string_view name);
    void waitForPreviousSubmission();

    // Copies and clears (d3d12_command_list_copy.cpp).
    void uploadToTexture(Texture& texture, rhi::TextureSlice slice, const void* data,
                         uint32_t packedRowBytes);
    void clearTextureByCopy(Texture& texture, const std::array<uint8_t, 16>& texel);

    // Compute and graphics (d3d12_command_list_draw.cpp).
    void bindTables(const std::vector<rhi::BindingLayoutHandle>& layouts,
                    const std::vector<rhi::BindingSet>& sets, const RootSignature& root, bool compute,
                    const std::string& pipelineName);
    void prepareDraw(const char* command);

    ContextHandle context_;
    std::shared_ptr<CommandListShared> shared_;
    rhi::QueueType type_;
    D3D12_COMMAND_LIST_TYPE listType_;
    std::string name_;
    ComPtr<ID3D12CommandAllocator> allocator_;
    ComPtr<ID3D12GraphicsCommandList> list_;
    Recording recording_ = Recording::Initial;

    rhi::StateTracker tracker_;
    bool automaticBarriers_ = true;
    std::vector<std::pair<NativeResource*, rhi::ResourceState>> commandUses_;
    std::vector<std::shared_ptr<NativeResource>> keptResources_;
    std::unordered_set<const NativeResource*> keptSet_;
    std::vector<std::shared_ptr<const void>> keptObjects_; // pipelines

    DescriptorTableAllocator viewTables_;
    DescriptorTableAllocator samplerTables_;
    UploadArena upload_;
    TimerQueries timers_;
    std::vector<rhi::TimerResult> previousResults_;
    bool hasPreviousResults_ = false;
    std::vector<bool> openRegions_; // innermost last; true: a timer, false: a marker

    ComPtr<ID3D12Fence> fence_;
    uint64_t fenceValue_ = 0;

    // Current compute or graphics state; pipelines are held by handle for the recording.
    rhi::ComputePipelineHandle computePipeline_;
    rhi::GraphicsPipelineHandle graphicsPipeline_;
    const RootSignature* root_ = nullptr;
    bool rootIsCompute_ = false;
    std::vector<WrittenBindingSet::Use> stateUses_;
    std::optional<rhi::IndexBufferBinding> indexBuffer_;
};

} // namespace lumina::d3d12
