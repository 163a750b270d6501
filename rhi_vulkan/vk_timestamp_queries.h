#pragma once
// GPU-timed regions of one command list: a timestamp query pair per region, in query pools
// the list owns, read back once its submission has finished.
#include "rhi/command_list.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

class TimestampQueries {
public:
    // `validBits`: the queue family's timestampValidBits; 0 means no timestamps, and every
    // region then reads as zero ticks.
    TimestampQueries(std::shared_ptr<Context> context, uint32_t validBits);
    ~TimestampQueries();
    TimestampQueries(const TimestampQueries&) = delete;
    TimestampQueries& operator=(const TimestampQueries&) = delete;

    // Forgets the regions and resets the pools, from the host when the device allows it,
    // else with commands recorded at the start of `commandBuffer`.
    void reset(VkCommandBuffer commandBuffer);

    // True when the next timestamp needs a new pool reset by a command, which may not be
    // recorded inside a render pass: the caller ends rendering first.
    bool nextNeedsCommandReset() const;

    void beginRegion(VkCommandBuffer commandBuffer, std::string_view name);
    void endRegion(VkCommandBuffer commandBuffer);
    size_t openRegions() const { return open_.size(); }
    const std::string& innermostOpenRegion() const;

    // The regions, in the order they began; only once the GPU has written them.
    std::vector<rhi::TimerResult> read() const;

private:
    uint32_t writeTimestamp(VkCommandBuffer commandBuffer);

    struct Region {
        std::string name;
        uint32_t beginQuery = 0;
        uint32_t endQuery = 0;
    };

    std::shared_ptr<Context> context_;
    uint32_t validBits_ = 0;
    std::vector<VkQueryPool> pools_;
    uint32_t used_ = 0;
    std::vector<Region> regions_;
    std::vector<size_t> open_; // indices into regions_
};

} // namespace lumina::vulkan
