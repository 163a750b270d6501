#include "rhi_vulkan/vk_upload_ring.h"

#include "rhi_vulkan/vk_buffer.h"

#include <algorithm>

namespace lumina::vulkan {

namespace {
constexpr uint64_t kMinimumChunkBytes = 1ull << 20;

uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return (value + alignment - 1) / alignment * alignment;
}
} // namespace

UploadRing::UploadRing(std::shared_ptr<Context> context, std::string debugName)
    : context_(std::move(context)), debugName_(std::move(debugName)) {}

UploadRing::~UploadRing() = default;

void UploadRing::addChunk(uint64_t minimumSize) {
    const uint64_t previous = chunks_.empty() ? 0 : chunks_.back().buffer->desc().size;
    const uint64_t size = std::max({kMinimumChunkBytes, previous * 2, minimumSize});
    rhi::BufferDesc desc;
    desc.size = size;
    desc.memory = rhi::MemoryType::Upload;
    desc.debugName = debugName_;
    chunks_.push_back({std::make_shared<Buffer>(context_, desc), 0});
}

UploadRing::Allocation UploadRing::allocate(uint64_t size, uint64_t alignment) {
    for (;; ++current_) {
        if (current_ == chunks_.size()) {
            addChunk(size);
        }
        Chunk& chunk = chunks_[current_];
        const uint64_t offset = alignUp(chunk.used, alignment);
        if (offset + size <= chunk.buffer->desc().size) {
            chunk.used = offset + size;
            return {chunk.buffer->handle(), offset, static_cast<uint8_t*>(chunk.buffer->map()) + offset};
        }
    }
}

void UploadRing::reset() {
    // A recording that needed several chunks will likely need them again: replace them with
    // one chunk as large as all of them, so that steady state uses a single buffer.
    if (chunks_.size() > 1) {
        uint64_t total = 0;
        for (const Chunk& chunk : chunks_) {
            total += chunk.buffer->desc().size;
        }
        chunks_.clear();
        addChunk(total);
    }
    for (Chunk& chunk : chunks_) {
        chunk.used = 0;
    }
    current_ = 0;
}

} // namespace lumina::vulkan
