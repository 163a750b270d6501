#include "rhi_d3d12/d3d12_timer.h"

#include "rhi_d3d12/d3d12_check.h"

namespace lumina::d3d12 {

namespace {
constexpr uint32_t kMaxTimestamps = 1024; // 512 regions per recording
}

TimerQueries::TimerQueries(ContextHandle context, D3D12_COMMAND_LIST_TYPE listType, uint64_t ticksPerSecond,
                           bool copyQueueTimestamps, std::string name)
    : context_(std::move(context)), listType_(listType), ticksPerSecond_(ticksPerSecond),
      supported_(listType != D3D12_COMMAND_LIST_TYPE_COPY || copyQueueTimestamps), name_(std::move(name)) {}

TimerQueries::~TimerQueries() {
    if (readback_) {
        readback_->Unmap(0, nullptr);
        context_->releaseMemory(readbackBytes_);
    }
}

void TimerQueries::create() {
    D3D12_QUERY_HEAP_DESC heapDesc{};
    heapDesc.Type = listType_ == D3D12_COMMAND_LIST_TYPE_COPY ? D3D12_QUERY_HEAP_TYPE_COPY_QUEUE_TIMESTAMP
                                                              : D3D12_QUERY_HEAP_TYPE_TIMESTAMP;
    heapDesc.Count = kMaxTimestamps;
    check(context_->device()->CreateQueryHeap(&heapDesc, IID_PPV_ARGS(&heap_)),
          "ID3D12Device::CreateQueryHeap(timestamps of '" + name_ + "')", *context_);
    setDebugName(heap_.Get(), "timestamps of " + name_);
    D3D12_RESOURCE_DESC desc{};
    desc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    desc.Width = kMaxTimestamps * sizeof(uint64_t);
    desc.Height = 1;
    desc.DepthOrArraySize = 1;
    desc.MipLevels = 1;
    desc.SampleDesc.Count = 1;
    desc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    readback_ =
        context_->createCommittedResource(D3D12_HEAP_TYPE_READBACK, desc, D3D12_RESOURCE_STATE_COPY_DEST,
                                          "timestamp readback of " + name_, readbackBytes_);
    void* mapped = nullptr;
    check(readback_->Map(0, nullptr, &mapped), "ID3D12Resource::Map(timestamp readback)", *context_);
    ticks_ = static_cast<const uint64_t*>(mapped);
}

void TimerQueries::begin(ID3D12GraphicsCommandList* list, std::string_view name) {
    if (!supported_) {
        throw rhi::Error("beginTimer('" + std::string(name) + "') on '" + name_ +
                         "': this device has no copy-queue timestamps");
    }
    if (used_ + 2 > kMaxTimestamps) {
        throw rhi::Error("beginTimer('" + std::string(name) + "') on '" + name_ + "': more than " +
                         std::to_string(kMaxTimestamps / 2) + " timed regions in one recording");
    }
    if (!heap_) {
        create();
    }
    regions_.push_back({std::string(name), used_, 0});
    open_.push_back(regions_.size() - 1);
    list->EndQuery(heap_.Get(), D3D12_QUERY_TYPE_TIMESTAMP, used_++);
}

void TimerQueries::end(ID3D12GraphicsCommandList* list) {
    if (open_.empty()) {
        throw rhi::Error("endTimer() on '" + name_ + "' without a matching beginTimer()");
    }
    Region& region = regions_[open_.back()];
    open_.pop_back();
    region.end = used_;
    list->EndQuery(heap_.Get(), D3D12_QUERY_TYPE_TIMESTAMP, used_++);
}

void TimerQueries::resolve(ID3D12GraphicsCommandList* list) {
    if (!open_.empty()) {
        throw rhi::Error("end() on '" + name_ + "': timer '" + regions_[open_.back()].name +
                         "' was never ended");
    }
    if (used_ > 0) {
        list->ResolveQueryData(heap_.Get(), D3D12_QUERY_TYPE_TIMESTAMP, 0, used_, readback_.Get(), 0);
    }
}

std::vector<rhi::TimerResult> TimerQueries::read() const {
    std::vector<rhi::TimerResult> results;
    results.reserve(regions_.size());
    for (const Region& region : regions_) {
        rhi::TimerResult result;
        result.name = region.name;
        result.beginTicks = ticks_[region.begin];
        result.endTicks = ticks_[region.end];
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
