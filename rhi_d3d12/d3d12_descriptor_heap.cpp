#include "rhi_d3d12/d3d12_descriptor_heap.h"

#include "rhi_d3d12/d3d12_check.h"

#include <algorithm>

namespace lumina::d3d12 {

namespace {
ComPtr<ID3D12DescriptorHeap> createHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type, uint32_t count,
                                        bool shaderVisible, const std::string& name) {
    D3D12_DESCRIPTOR_HEAP_DESC desc{};
    desc.Type = type;
    desc.NumDescriptors = count;
    desc.Flags = shaderVisible ? D3D12_DESCRIPTOR_HEAP_FLAG_SHADER_VISIBLE : D3D12_DESCRIPTOR_HEAP_FLAG_NONE;
    ComPtr<ID3D12DescriptorHeap> heap;
    check(device->CreateDescriptorHeap(&desc, IID_PPV_ARGS(&heap)),
          "ID3D12Device::CreateDescriptorHeap(" + name + ", " + std::to_string(count) + " descriptors)");
    setDebugName(heap.Get(), name);
    return heap;
}
} // namespace

StagingDescriptorHeap::StagingDescriptorHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type,
                                             uint32_t descriptorsPerHeap, std::string name)
    : device_(device), type_(type), descriptorsPerHeap_(descriptorsPerHeap),
      increment_(device->GetDescriptorHandleIncrementSize(type)), name_(std::move(name)) {}

void StagingDescriptorHeap::grow() {
    const std::string heapName = name_ + " #" + std::to_string(heaps_.size());
    heaps_.push_back(createHeap(device_, type_, descriptorsPerHeap_, false, heapName));
    const D3D12_CPU_DESCRIPTOR_HANDLE start = cpuHeapStart(heaps_.back().Get());
    for (uint32_t i = descriptorsPerHeap_; i-- > 0;) {
        free_.push_back({start.ptr + size_t(i) * increment_});
    }
}

D3D12_CPU_DESCRIPTOR_HANDLE StagingDescriptorHeap::allocate() {
    std::lock_guard lock(mutex_);
    if (free_.empty()) {
        grow();
    }
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = free_.back();
    free_.pop_back();
    ++allocated_;
    return handle;
}

void StagingDescriptorHeap::free(D3D12_CPU_DESCRIPTOR_HANDLE handle) {
    std::lock_guard lock(mutex_);
    free_.push_back(handle);
    --allocated_;
}

uint32_t StagingDescriptorHeap::allocatedCount() const {
    std::lock_guard lock(mutex_);
    return allocated_;
}

ShaderVisibleDescriptorHeap::ShaderVisibleDescriptorHeap(ID3D12Device* device,
                                                         D3D12_DESCRIPTOR_HEAP_TYPE type,
                                                         uint32_t descriptorCount, uint32_t pageSize,
                                                         std::string name)
    : type_(type), pageSize_(pageSize), pageCount_(descriptorCount / pageSize),
      increment_(device->GetDescriptorHandleIncrementSize(type)), name_(std::move(name)) {
    heap_ = createHeap(device, type, pageCount_ * pageSize_, true, name_);
    cpuStart_ = cpuHeapStart(heap_.Get());
    gpuStart_ = gpuHeapStart(heap_.Get());
    for (uint32_t page = 0; page < pageCount_; ++page) {
        freePages_.push_back(page);
    }
}

uint32_t ShaderVisibleDescriptorHeap::acquirePage() {
    std::lock_guard lock(mutex_);
    if (freePages_.empty()) {
        throw rhi::Error(name_ + ": all " + std::to_string(pageCount_) + " pages of " +
                         std::to_string(pageSize_) +
                         " descriptors are held by command lists that have not been reset (too many lists in "
                         "flight, or one list binds too much between begin() calls)");
    }
    const uint32_t page = freePages_.front();
    freePages_.pop_front();
    return page;
}

void ShaderVisibleDescriptorHeap::releasePage(uint32_t page) {
    std::lock_guard lock(mutex_);
    freePages_.push_back(page);
}

D3D12_CPU_DESCRIPTOR_HANDLE ShaderVisibleDescriptorHeap::cpuHandle(uint32_t index) const {
    return {cpuStart_.ptr + size_t(index) * increment_};
}

D3D12_GPU_DESCRIPTOR_HANDLE ShaderVisibleDescriptorHeap::gpuHandle(uint32_t index) const {
    return {gpuStart_.ptr + uint64_t(index) * increment_};
}

DescriptorTable DescriptorTableAllocator::allocate(uint32_t count) {
    if (count > heap_.pageSize()) {
        throw rhi::Error("a descriptor table of " + std::to_string(count) +
                         " descriptors exceeds the page size (" + std::to_string(heap_.pageSize()) + ")");
    }
    if (pages_.empty() || used_ + count > heap_.pageSize()) {
        pages_.push_back(heap_.acquirePage());
        used_ = 0;
    }
    const uint32_t index = pages_.back() * heap_.pageSize() + used_;
    used_ += count;
    return {heap_.cpuHandle(index), heap_.gpuHandle(index), index};
}

DescriptorTable DescriptorTableAllocator::tableOf(ID3D12Device* device,
                                                  const std::vector<D3D12_CPU_DESCRIPTOR_HANDLE>& sources) {
    std::vector<size_t> key;
    key.reserve(sources.size());
    for (const D3D12_CPU_DESCRIPTOR_HANDLE& source : sources) {
        key.push_back(source.ptr);
    }
    if (const auto found = written_.find(key); found != written_.end()) {
        return found->second;
    }
    const DescriptorTable table = allocate(static_cast<uint32_t>(sources.size()));
    const D3D12_DESCRIPTOR_HEAP_TYPE type = heap_.type();
    const UINT increment = device->GetDescriptorHandleIncrementSize(type);
    for (size_t i = 0; i < sources.size(); ++i) {
        device->CopyDescriptorsSimple(1, {table.cpu.ptr + i * increment}, sources[i], type);
    }
    written_.emplace(std::move(key), table);
    return table;
}

void DescriptorTableAllocator::reset() {
    for (uint32_t page : pages_) {
        heap_.releasePage(page);
    }
    pages_.clear();
    used_ = 0;
    written_.clear();
}

} // namespace lumina::d3d12
