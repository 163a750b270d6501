#pragma once
// GPU-timed regions of one command list: a timestamp query heap written with EndQuery at each
// region's start and end, resolved into a readback buffer when the list ends, and read once
// its submission has finished.
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
    void create();

    ContextHandle context_;
    D3D12_COMMAND_LIST_TYPE listType_;
    uint64_t ticksPerSecond_;
    bool supported_;
    std::string name_;
    ComPtr<ID3D12QueryHeap> heap_;
    ComPtr<ID3D12Resource> readback_;
    uint64_t readbackBytes_ = 0;
    const uint64_t* ticks_ = nullptr;
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
