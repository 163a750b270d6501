#include "rhi_d3d12/d3d12_upload.h"

#include "rhi_d3d12/d3d12_check.h"

#include <algorithm>

namespace lumina::d3d12 {

namespace {
constexpr uint64_t kPageSize = 4ull << 20; // larger requests get a page of their own size
}

UploadArena::~UploadArena() {
    for (Page& page : pages_) {
        page.resource->Unmap(0, nullptr);
        context_->releaseMemory(page.allocatedBytes);
    }
}

UploadAllocation UploadArena::allocate(uint64_t size, uint64_t alignment) {
    while (current_ < pages_.size()) {
        const uint64_t offset = (used_ + alignment - 1) / alignment * alignment;
        if (offset + size <= pages_[current_].size) {
            used_ = offset + size;
            return {pages_[current_].resource.Get(), offset, pages_[current_].cpu + offset};
        }
        ++current_;
        used_ = 0;
    }
    Page page;
    page.size = std::max(kPageSize, size);
    D3D12_RESOURCE_DESC desc{};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    desc.Width = page.size;
    desc.Height = 1;
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.SampleDesc.Count = 1;
    desc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    const std::string pageName = name_ + " upload page " + std::to_string(pages_.size());
    page.resource = context_->createCommittedResource(
        D3D12_HEAP_TYPE_UPLOAD, desc, D3D12_RESOURCE_STATE_GENERIC_READ, pageName, page.allocatedBytes);
    void* cpu = nullptr;
    check(page.resource->Map(0, nullptr, &cpu), "ID3D12Resource::Map('" + pageName + "')", *context_);
    page.cpu = static_cast<uint8_t*>(cpu);
    pages_.push_back(std::move(page));
    current_ = pages_.size() - 1;
    used_ = size;
    return {pages_[current_].resource.Get(), 0, pages_[current_].cpu};
}

void UploadArena::reset() {
    current_ = 0;
    used_ = 0;
}

} // namespace lumina::d3d12
