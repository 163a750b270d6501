#pragma once
// GPU-timed regions of one command list: timestamp query heaps (a new one whenever the last is
// full, so a recording may time any number of regions) written with EndQuery at each region's
// start and end, resolved into readback buffers when the list ends, and read once its
// submission has finished.
#include "rhi/command_list.h"
#include "rhi_d3d12/d3d12_context.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::d3d12 {

class TimerQueries {
public:
    // ticksPerSecond: the timestamp frequency of the queue the list is submitted to.
    TimerQueries(ContextHandle context, D3D12_COMMAND_LIST_TYPE listType, uint64_t ticksPerSecond,
                 bool copyQueueTimestamps, std::string name);
    ~TimerQueries();
    TimerQueries(const TimerQueries&) = delete;
    TimerQueries& operator=(const TimerQueries&) = delete;

    void begin(ID3D12GraphicsCommandList* list, std::string_view name);
    void end(ID3D12GraphicsCommandList* list);
    // At the end of recording; throws rhi::Error naming a region that was never ended.
    void resolve(ID3D12GraphicsCommandList* list);
    // The regions of the recording resolved last; only after its submission has finished.
    std::vector<rhi::TimerResult> read() const;
    void reset();

private:
    void addBlock();
    void writeTimestamp(ID3D12GraphicsCommandList* list);
    uint64_t ticks(uint32_t timestamp) const;

    ContextHandle context_;
    D3D12_COMMAND_LIST_TYPE listType_;
    uint64_t ticksPerSecond_;
    bool supported_;
    std::string name_;
    // One query heap and its mapped readback buffer per kTimestampsPerHeap timestamps.
    struct Block {
        ComPtr<ID3D12QueryHeap> heap;
        ComPtr<ID3D12Resource> readback;
        uint64_t readbackBytes = 0;
        const uint64_t* ticks = nullptr;
    };
    std::vector<Block> blocks_;
    struct Region {
        std::string name;
        uint32_t begin = 0;
        uint32_t end = 0;
    };
    std::vector<Region> regions_;
    std::vector<size_t> open_;
    uint32_t used_ = 0;
};

} // namespace lumina::d3d12
