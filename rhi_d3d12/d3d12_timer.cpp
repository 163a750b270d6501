#include "rhi_d3d12/d3d12_timer.h"

#include "rhi_d3d12/d3d12_check.h"

#include <algorithm>

namespace lumina::d3d12 {

namespace {
// Timestamps per query heap (512 regions); a recording that needs more gets another heap, so a
// test or bench that records hundreds of frames into one list has no limit (as on Vulkan).
constexpr uint32_t kTimestampsPerHeap = 1024;
} // namespace

TimerQueries::TimerQueries(ContextHandle context, D3D12_COMMAND_LIST_TYPE listType, uint64_t ticksPerSecond,
                           bool copyQueueTimestamps, std::string name)
    : context_(std::move(context)), listType_(listType), ticksPerSecond_(ticksPerSecond),
      supported_(listType != D3D12_COMMAND_LIST_TYPE_COPY || copyQueueTimestamps), name_(std::move(name)) {}

TimerQueries::~TimerQueries() {
    for (Block& block : blocks_) {
        block.readback->Unmap(0, nullptr);
        context_->releaseMemory(block.readbackBytes);
    }
}

void TimerQueries::addBlock() {
    Block block;
    const std::string name = name_ + (blocks_.empty() ? "" : " #" + std::to_string(blocks_.size() + 1));
    D3D12_QUERY_HEAP_DESC heapDesc{};
    heapDesc.Type = listType_ == D3D12_COMMAND_LIST_TYPE_COPY ? D3D12_QUERY_HEAP_TYPE_COPY_QUEUE_TIMESTAMP
                                                              : D3D12_QUERY_HEAP_TYPE_TIMESTAMP;
    heapDesc.Count = kTimestampsPerHeap;
    check(context_->device()->CreateQueryHeap(&heapDesc, IID_PPV_ARGS(&block.heap)),
          "ID3D12Device::CreateQueryHeap(timestamps of '" + name + "')", *context_);
    setDebugName(block.heap.Get(), "timestamps of " + name);
    D3D12_RESOURCE_DESC desc{};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    desc.Width = kTimestampsPerHeap * sizeof(uint64_t);
    desc.Height = 1;
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.SampleDesc.Count = 1;
    desc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    block.readback =
        context_->createCommittedResource(D3D12_HEAP_TYPE_READBACK, desc, D3D12_RESOURCE_STATE_COPY_DEST,
                                          "timestamp readback of " + name, block.readbackBytes);
    void* mapped = nullptr;
    check(block.readback->Map(0, nullptr, &mapped), "ID3D12Resource::Map(timestamp readback)", *context_);
    block.ticks = static_cast<const uint64_t*>(mapped);
    blocks_.push_back(std::move(block));
}

void TimerQueries::writeTimestamp(ID3D12GraphicsCommandList* list) {
    if (used_ / kTimestampsPerHeap >= blocks_.size()) {
        addBlock();
    }
    list->EndQuery(blocks_[used_ / kTimestampsPerHeap].heap.Get(), D3D12_QUERY_TYPE_TIMESTAMP,
                   used_ % kTimestampsPerHeap);
    ++used_;
}

uint64_t TimerQueries::ticks(uint32_t timestamp) const {
    return blocks_[timestamp / kTimestampsPerHeap].ticks[timestamp % kTimestampsPerHeap];
}

void TimerQueries::begin(ID3D12GraphicsCommandList* list, std::string_view name) {
    if (!supported_) {
        throw rhi::Error("beginTimer('" + std::string(name) + "') on '" + name_ +
                         "': this device has no copy-queue timestamps");
    }
    regions_.push_back({std::string(name), used_, 0});
    open_.push_back(regions_.size() - 1);
    writeTimestamp(list);
}

void TimerQueries::end(ID3D12GraphicsCommandList* list) {
    if (open_.empty()) {
        throw rhi::Error("endTimer() on '" + name_ + "' without a matching beginTimer()");
    }
    Region& region = regions_[open_.back()];
    open_.pop_back();
    region.end = used_;
    writeTimestamp(list);
}

void TimerQueries::resolve(ID3D12GraphicsCommandList* list) {
    if (!open_.empty()) {
        throw rhi::Error("end() on '" + name_ + "': timer '" + regions_[open_.back()].name +
                         "' was never ended");
    }
    for (uint32_t first = 0; first < used_; first += kTimestampsPerHeap) {
        const Block& block = blocks_[first / kTimestampsPerHeap];
        list->ResolveQueryData(block.heap.Get(), D3D12_QUERY_TYPE_TIMESTAMP, 0,
                               std::min(used_ - first, kTimestampsPerHeap), block.readback.Get(), 0);
    }
}

std::vector<rhi::TimerResult> TimerQueries::read() const {
    std::vector<rhi::TimerResult> results;
    results.reserve(regions_.size());
    for (const Region& region : regions_) {
        rhi::TimerResult result;
        result.name = region.name;
        result.beginTicks = ticks(region.begin);
        result.endTicks = ticks(region.end);
        const uint64_t elapsed =
            result.endTicks >= result.beginTicks ? result.endTicks - result.beginTicks : 0;
        result.milliseconds = ticksPerSecond_ ? double(elapsed) * 1000.0 / double(ticksPerSecond_) : 0.0;
        results.push_back(std::move(result));
    }
    return results;
}

void TimerQueries::reset() {
    regions_.clear();
    open_.clear();
    used_ = 0;
}

} // namespace lumina::d3d12
