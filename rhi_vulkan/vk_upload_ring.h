#pragma once
// Host-visible staging memory a command list copies from (writeBuffer, writeTexture).
// Linear allocation in chunks that grow as needed; everything is recycled when the list
// begins again, after the GPU has finished with it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Buffer;
class Context;

class UploadRing {
public:
    UploadRing(std::shared_ptr<Context> context, std::string debugName);
    ~UploadRing();

    struct Allocation {
        VkBuffer buffer = VK_NULL_HANDLE;
        uint64_t offset = 0;
        void* data = nullptr;
    };
    Allocation allocate(uint64_t size, uint64_t alignment);
    // Only once the GPU is done with every allocation made so far.
    void reset();

private:
    struct Chunk {
        std::shared_ptr<Buffer> buffer;
        uint64_t used = 0;
    };
    void addChunk(uint64_t minimumSize);

    std::shared_ptr<Context> context_;
    std::string debugName_;
    std::vector<Chunk> chunks_;
    size_t current_ = 0;
};

} // namespace lumina::vulkan
