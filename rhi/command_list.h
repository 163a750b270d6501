#pragma once
// Command recording. Command lists track every resource's state and place the barriers a
// copy, dispatch or draw needs before recording it (UAV-to-UAV included), unless automatic
// barriers are switched off for code that wants explicit control.
#include "rhi/binding.h"
#include "rhi/pipeline.h"
#include "rhi/resource.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::rhi {

enum class QueueType : uint8_t { Graphics, Compute, Copy };
const char* queueTypeName(QueueType type); // "graphics", "compute", "copy"

struct ComputeState {
    ComputePipelineHandle pipeline;
    std::vector<BindingSet> bindings; // one per register space, in space order
};

struct Attachment {
    TextureHandle texture;
    uint32_t mipLevel = 0;
    uint32_t arrayLayer = 0; // the layer rendered to: cube face f of cube c is 6c + f
};

struct Viewport {
    float x = 0, y = 0, width = 0, height = 0;
    float minDepth = 0, maxDepth = 1;
};

struct Rect {
    int32_t x = 0, y = 0;
    uint32_t width = 0, height = 0;
};

enum class IndexFormat : uint8_t { Uint16, Uint32 };

struct IndexBufferBinding {
    BufferHandle buffer;
    IndexFormat format = IndexFormat::Uint32;
    uint64_t offset = 0;
};

// Everything a draw needs. Attachments are loaded, never cleared: clears are commands of
// their own (clearColor, clearDepth), so a render pass can be split for barriers at will.
struct GraphicsState {
    GraphicsPipelineHandle pipeline;
    std::vector<Attachment> colorAttachments;
    std::optional<Attachment> depthAttachment;
    std::vector<BindingSet> bindings;
    Viewport viewport;           // width 0: the first attachment's full size
    std::optional<Rect> scissor; // none: the viewport
    std::optional<IndexBufferBinding> indexBuffer;
};

struct DrawArgs {
    uint32_t vertexOrIndexCount = 0;
    uint32_t instanceCount = 1;
    uint32_t firstVertexOrIndex = 0;
    int32_t vertexOffset = 0; // drawIndexed only
    uint32_t firstInstance = 0;
};

// One timed region: GPU time between beginTimer(name) and endTimer().
struct TimerResult {
    std::string name;
    double milliseconds = 0.0;
    uint64_t beginTicks = 0; // raw timestamps, for ordering checks
    uint64_t endTicks = 0;
};

class ICommandList {
public:
    virtual ~ICommandList() = default;

    virtual QueueType queueType() const = 0;

    // Starts recording. Waits for this list's previous submission to finish, then releases
    // the resources it kept alive, its transient descriptors and its upload memory.
    virtual void begin() = 0;
    virtual void end() = 0;

    // --- state tracking -------------------------------------------------------------
    virtual void setAutomaticBarriers(bool enabled) = 0;
    virtual void transition(IResource& resource, ResourceState state) = 0;
    virtual void uavBarrier(IResource& resource) = 0;
    virtual void commitBarriers() = 0;

    // --- copies and uploads ---------------------------------------------------------
    virtual void copyBuffer(IBuffer& dst, uint64_t dstOffset, IBuffer& src, uint64_t srcOffset,
                            uint64_t size) = 0;
    // Buffer rows are rowPitch bytes apart (a multiple of kTextureCopyRowAlignment), from an
    // offset that is a multiple of kTextureCopyOffsetAlignment, on every backend
    // (rhi/validation.h); a 3D slice copies every depth slice, one after another.
    virtual void copyBufferToTexture(ITexture& dst, TextureSlice slice, IBuffer& src, uint64_t srcOffset,
                                     uint32_t rowPitch) = 0;
    virtual void copyTextureToBuffer(IBuffer& dst, uint64_t dstOffset, uint32_t rowPitch, ITexture& src,
                                     TextureSlice slice) = 0;
    virtual void copyTexture(ITexture& dst, TextureSlice dstSlice, ITexture& src, TextureSlice srcSlice) = 0;
    // Copies host data through this list's upload memory; data may be freed on return.
    virtual void writeBuffer(IBuffer& dst, const void* data, uint64_t size, uint64_t dstOffset = 0) = 0;
    // Tightly packed rows (width x bytesPerTexel), all depth slices of a 3D texture.
    virtual void writeTexture(ITexture& dst, TextureSlice slice, const void* data) = 0;

    virtual void fillBuffer(IBuffer& dst, uint32_t value) = 0;
    virtual void clearColor(ITexture& texture, std::array<float, 4> value) = 0;
    virtual void clearColorUint(ITexture& texture, std::array<uint32_t, 4> value) = 0;
    virtual void clearDepth(ITexture& texture, float depth) = 0;

    // --- compute --------------------------------------------------------------------
    virtual void setComputeState(const ComputeState& state) = 0;
    // Root constants on D3D12, push constants on Vulkan; valid until the next set*State.
    virtual void setPushConstants(const void* data, uint32_t size) = 0;
    virtual void dispatch(uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1) = 0;
    virtual void dispatchIndirect(IBuffer& args, uint64_t offset) = 0;

    // --- graphics -------------------------------------------------------------------
    virtual void setGraphicsState(const GraphicsState& state) = 0;
    virtual void draw(const DrawArgs& args) = 0;
    virtual void drawIndexed(const DrawArgs& args) = 0;

    // --- debugging and timing -------------------------------------------------------
    virtual void beginMarker(std::string_view name) = 0;
    virtual void endMarker() = 0;
    // A named GPU-timed region; also a debug marker. Regions may nest.
    virtual void beginTimer(std::string_view name) = 0;
    virtual void endTimer() = 0;
    // The timed regions of the last completed submission, in the order they began.
    // Throws if that submission has not finished.
    virtual std::vector<TimerResult> timerResults() = 0;

    template <typename T>
    void pushConstants(const T& value) {
        setPushConstants(&value, static_cast<uint32_t>(sizeof(T)));
    }
};

using CommandListHandle = std::shared_ptr<ICommandList>;

} // namespace lumina::rhi
