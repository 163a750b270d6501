#pragma once
// Descriptor heaps.
//
// Views are created once, in CPU-only staging heaps, and cached by the resource that owns
// them (d3d12_buffer.cpp, d3d12_texture.cpp); RTVs and DSVs live in staging heaps of their
// own kind. At bind time a command list copies a binding set's views into the one
// shader-visible heap of each kind (CBV/SRV/UAV, sampler), into space it takes from a
// ring of pages: a list takes pages while it records and hands them back at its next
// begin(), after its previous submission has finished. Pages are reused oldest-freed first,
// so the heap is consumed as a ring across the frames in flight, and nothing bound has to
// outlive the submission that used it.
#include "rhi_d3d12/d3d12_headers.h"

#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace lumina::d3d12 {

// A growable, thread-safe pool of CPU-only descriptors of one heap type.
class StagingDescriptorHeap {
public:
    StagingDescriptorHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type, uint32_t descriptorsPerHeap,
                          std::string name);
    StagingDescriptorHeap(const StagingDescriptorHeap&) = delete;
    StagingDescriptorHeap& operator=(const StagingDescriptorHeap&) = delete;

    D3D12_CPU_DESCRIPTOR_HANDLE allocate();
    void free(D3D12_CPU_DESCRIPTOR_HANDLE handle);
    D3D12_DESCRIPTOR_HEAP_TYPE type() const { return type_; }
    uint32_t allocatedCount() const;

private:
    void grow();

    ID3D12Device* device_;
    D3D12_DESCRIPTOR_HEAP_TYPE type_;
    uint32_t descriptorsPerHeap_;
    uint32_t increment_;
    std::string name_;
    mutable std::mutex mutex_;
    std::vector<ComPtr<ID3D12DescriptorHeap>> heaps_;
    std::vector<D3D12_CPU_DESCRIPTOR_HANDLE> free_;
    uint32_t allocated_ = 0;
};

// The shader-visible heap of one type, handed out in pages of `pageSize` descriptors.
class ShaderVisibleDescriptorHeap {
public:
    ShaderVisibleDescriptorHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type,
                                uint32_t descriptorCount, uint32_t pageSize, std::string name);
    ShaderVisibleDescriptorHeap(const ShaderVisibleDescriptorHeap&) = delete;
    ShaderVisibleDescriptorHeap& operator=(const ShaderVisibleDescriptorHeap&) = delete;

    ID3D12DescriptorHeap* heap() const { return heap_.Get(); }
    uint32_t pageSize() const { return pageSize_; }
    D3D12_DESCRIPTOR_HEAP_TYPE type() const { return type_; }
    // Throws rhi::Error when every page is held by a command list that has not been reset.
    uint32_t acquirePage();
    void releasePage(uint32_t page);

    D3D12_CPU_DESCRIPTOR_HANDLE cpuHandle(uint32_t index) const;
    D3D12_GPU_DESCRIPTOR_HANDLE gpuHandle(uint32_t index) const;

private:
    ComPtr<ID3D12DescriptorHeap> heap_;
    D3D12_DESCRIPTOR_HEAP_TYPE type_;
    uint32_t pageSize_;
    uint32_t pageCount_;
    uint32_t increment_;
    std::string name_;
    D3D12_CPU_DESCRIPTOR_HANDLE cpuStart_{};
    D3D12_GPU_DESCRIPTOR_HANDLE gpuStart_{};
    std::mutex mutex_;
    std::deque<uint32_t> freePages_; // FIFO: the page freed longest ago is reused first
};

// One contiguous range of a shader-visible heap, valid until the owning list's next begin().
struct DescriptorTable {
    D3D12_CPU_DESCRIPTOR_HANDLE cpu{};
    D3D12_GPU_DESCRIPTOR_HANDLE gpu{};
    uint32_t firstIndex = 0;
};

// A command list's cursor into a shader-visible heap.
class DescriptorTableAllocator {
public:
    explicit DescriptorTableAllocator(ShaderVisibleDescriptorHeap& heap) : heap_(heap) {}
    ~DescriptorTableAllocator() { reset(); }
    DescriptorTableAllocator(const DescriptorTableAllocator&) = delete;
    DescriptorTableAllocator& operator=(const DescriptorTableAllocator&) = delete;

    DescriptorTable allocate(uint32_t count);
    // A table holding exactly `sources` (CPU-only descriptors, in table order): the one this list
    // already wrote for the same sources since its last reset(), else a new one. For samplers,
    // which are few and long-lived: a frame of `city` binds one sampler table for each of its
    // thousands of capture draws, more than the 2048 samplers a shader-visible heap may hold.
    DescriptorTable tableOf(ID3D12Device* device, const std::vector<D3D12_CPU_DESCRIPTOR_HANDLE>& sources);
    // Returns every page; only once the GPU no longer reads them.
    void reset();

private:
    ShaderVisibleDescriptorHeap& heap_;
    std::vector<uint32_t> pages_;
    uint32_t used_ = 0;                                      // descriptors used in pages_.back()
    std::map<std::vector<size_t>, DescriptorTable> written_; // tableOf's tables, by source pointers
};

} // namespace lumina::d3d12
