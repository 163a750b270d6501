#include "rhi_vulkan/vk_timestamp_queries.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <algorithm>

namespace lumina::vulkan {

namespace {
constexpr uint32_t kQueriesPerPool = 64;
}

TimestampQueries::TimestampQueries(std::shared_ptr<Context> context, uint32_t validBits)
    : context_(std::move(context)), validBits_(validBits) {}

TimestampQueries::~TimestampQueries() {
    for (VkQueryPool pool : pools_) {
        vkDestroyQueryPool(context_->device(), pool, nullptr);
    }
}

void TimestampQueries::reset(VkCommandBuffer commandBuffer) {
    for (VkQueryPool pool : pools_) {
        if (context_->features().hostQueryReset) {
            vkResetQueryPool(context_->device(), pool, 0, kQueriesPerPool);
        } else {
            vkCmdResetQueryPool(commandBuffer, pool, 0, kQueriesPerPool);
        }
    }
    used_ = 0;
    regions_.clear();
    open_.clear();
}

bool TimestampQueries::nextNeedsCommandReset() const {
    return validBits_ != 0 && used_ == pools_.size() * kQueriesPerPool &&
           !context_->features().hostQueryReset;
}

uint32_t TimestampQueries::writeTimestamp(VkCommandBuffer commandBuffer) {
    if (validBits_ == 0) {
        return 0;
    }
    if (used_ == pools_.size() * kQueriesPerPool) {
        auto info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = kQueriesPerPool;
        VkQueryPool pool = VK_NULL_HANDLE;
        check(vkCreateQueryPool(context_->device(), &info, nullptr, &pool), "vkCreateQueryPool",
              "timestamps");
        pools_.push_back(pool);
        if (context_->features().hostQueryReset) {
            vkResetQueryPool(context_->device(), pool, 0, kQueriesPerPool);
        } else {
            vkCmdResetQueryPool(commandBuffer, pool, 0, kQueriesPerPool);
        }
    }
    const uint32_t query = used_++;
    // ALL_COMMANDS: the timestamp is taken once every earlier command has finished, so a
    // region measures exactly the work recorded inside it.
    vkCmdWriteTimestamp2(commandBuffer, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[query / kQueriesPerPool],
                         query % kQueriesPerPool);
    return query;
}

void TimestampQueries::beginRegion(VkCommandBuffer commandBuffer, std::string_view name) {
    Region region;
    region.name = std::string(name);
    region.beginQuery = writeTimestamp(commandBuffer);
    open_.push_back(regions_.size());
    regions_.push_back(std::move(region));
}

void TimestampQueries::endRegion(VkCommandBuffer commandBuffer) {
    if (open_.empty()) {
        throw rhi::Error("endTimer without a matching beginTimer");
    }
    regions_[open_.back()].endQuery = writeTimestamp(commandBuffer);
    open_.pop_back();
}

const std::string& TimestampQueries::innermostOpenRegion() const {
    return regions_.at(open_.back()).name;
}

std::vector<rhi::TimerResult> TimestampQueries::read() const {
    std::vector<uint64_t> ticks(used_);
    for (uint32_t first = 0; first < used_; first += kQueriesPerPool) {
        const uint32_t count = std::min(kQueriesPerPool, used_ - first);
        check(vkGetQueryPoolResults(context_->device(), pools_[first / kQueriesPerPool], 0, count,
                                    count * sizeof(uint64_t), ticks.data() + first, sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults", "timestamps");
    }
    const uint64_t mask = validBits_ >= 64 ? ~0ull : (1ull << validBits_) - 1;
    const double nanosecondsPerTick = context_->limits().timestampPeriod;
    std::vector<rhi::TimerResult> results;
    for (const Region& region : regions_) {
        rhi::TimerResult result;
        result.name = region.name;
        if (validBits_ != 0) {
            result.beginTicks = ticks[region.beginQuery] & mask;
            result.endTicks = ticks[region.endQuery] & mask;
            // Wrapped counters (narrow validBits) would read as negative: report zero.
            const uint64_t elapsed =
                result.endTicks >= result.beginTicks ? result.endTicks - result.beginTicks : 0;
            result.milliseconds = static_cast<double>(elapsed) * nanosecondsPerTick * 1e-6;
        }
        results.push_back(std::move(result));
    }
    return results;
}

} // namespace lumina::vulkan
