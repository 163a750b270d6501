#pragma once
// A command list's upload memory: pages of upload-heap buffers that writeBuffer, writeTexture
// and the copy-based clears fill from the CPU and copy from on the GPU. Pages are kept
// across begin() calls and reused once the list's previous submission has finished.
#include "rhi_d3d12/d3d12_context.h"

#include <cstdint>
#include <vector>

namespace lumina::d3d12 {

struct UploadAllocation {
    ID3D12Resource* resource = nullptr;
    uint64_t offset = 0;
    uint8_t* cpu = nullptr;
};

class UploadArena {
public:
    UploadArena(ContextHandle context, std::string name)
        : context_(std::move(context)), name_(std::move(name)) {}
    ~UploadArena();
    UploadArena(const UploadArena&) = delete;
    UploadArena& operator=(const UploadArena&) = delete;

    UploadAllocation allocate(uint64_t size, uint64_t alignment);
    // Makes every page free again; only once the GPU has finished reading them.
    void reset();

private:
    struct Page {
        ComPtr<ID3D12Resource> resource;
        uint8_t* cpu = nullptr;
        uint64_t size = 0;
        uint64_t allocatedBytes = 0;
    };
    ContextHandle context_;
    std::string name_;
    std::vector<Page> pages_;
    size_t current_ = 0;
    uint64_t used_ = 0;
};

} // namespace lumina::d3d12
