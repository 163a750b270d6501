// GPU timers and debug markers.
#include "shaders/common/constants_shared.h"
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <string>

namespace lumina::test {
namespace {

using TimerTest = GpuTest;
using gpu::ChainConstants;

constexpr uint32_t kCount = 4096, kGroupSize = LUMINA_LINEAR_GROUP_SIZE;

TEST_P(TimerTest, RegionsAreNamedNonZeroAndOrdered) {
    LUMINA_REQUIRE_KERNELS();
    // chain_seed, not accumulate: every D3D12 build has it (docs/d3d12.md, kernels without DXBC).
    const ComputeKernel kernel =
        loadComputeKernel("rhi_tests/chain_seed", {{rhi::BindingType::BufferUAV, 0}}, sizeof(ChainConstants));
    rhi::BufferHandle data =
        device().createBuffer({.size = kCount * 4,
                               .structStride = 4,
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "timed data"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->beginTimer("frame");
    list->beginTimer("clear");
    list->fillBuffer(*data, 0);
    list->endTimer();
    list->beginMarker("seed passes");
    list->beginTimer("seed");
    list->setComputeState(
        {.pipeline = kernel.pipeline,
         .bindings = {{kernel.layout, {rhi::BindingSetItem::rwStructuredBuffer(0, data)}}}});
    for (uint32_t pass = 0; pass < 4; ++pass) {
        list->pushConstants(ChainConstants{kCount, 1, pass, 0});
        list->dispatch(kCount / kGroupSize);
    }
    list->endTimer();
    list->endMarker();
    list->endTimer();
    list->end();
    submitAndWait(*list);

    const std::vector<rhi::TimerResult> timers = list->timerResults();
    ASSERT_EQ(timers.size(), 3u);
    EXPECT_EQ(timers[0].name, "frame");
    EXPECT_EQ(timers[1].name, "clear");
    EXPECT_EQ(timers[2].name, "seed");
    for (const rhi::TimerResult& timer : timers) {
        SCOPED_TRACE(timer.name);
        EXPECT_GT(timer.beginTicks, 0u);
        EXPECT_LE(timer.beginTicks, timer.endTicks);
        EXPECT_GE(timer.milliseconds, 0.0);
    }
    // Nested regions lie inside their parent, sequential ones follow each other.
    EXPECT_LE(timers[0].beginTicks, timers[1].beginTicks);
    EXPECT_LE(timers[1].endTicks, timers[2].beginTicks);
    EXPECT_LE(timers[2].endTicks, timers[0].endTicks);
    EXPECT_GT(timers[0].endTicks, timers[0].beginTicks) << "the whole frame took no time";
    const double period = device().capabilities().timestampPeriodNs;
    EXPECT_NEAR(timers[0].milliseconds, double(timers[0].endTicks - timers[0].beginTicks) * period * 1e-6,
                1e-9);

    // The results stay those of the last completed submission while the list records again.
    list->begin();
    EXPECT_EQ(list->timerResults().size(), 3u);
    list->end();
    submitAndWait(*list);
    EXPECT_TRUE(list->timerResults().empty());
}

TEST_P(TimerTest, CopiesAreTimedWithoutKernels) {
    constexpr uint64_t kBytes = 4u << 20;
    rhi::BufferHandle source = device().createBuffer({.size = kBytes, .debugName = "timed source"});
    rhi::BufferHandle target = device().createBuffer({.size = kBytes, .debugName = "timed target"});
    const std::vector<uint32_t> pattern(kBytes / 4, 0x5eed5eedu);
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->beginTimer("copies");
    list->beginTimer("upload");
    list->writeBuffer(*source, pattern.data(), kBytes);
    list->endTimer();
    list->beginMarker("copy");
    list->beginTimer("copy");
    list->copyBuffer(*target, 0, *source, 0, kBytes);
    list->endTimer();
    list->endMarker();
    list->endTimer();
    list->end();
    submitAndWait(*list);

    const std::vector<rhi::TimerResult> timers = list->timerResults();
    ASSERT_EQ(timers.size(), 3u);
    EXPECT_EQ(timers[0].name, "copies");
    EXPECT_EQ(timers[1].name, "upload");
    EXPECT_EQ(timers[2].name, "copy");
    for (const rhi::TimerResult& timer : timers) {
        EXPECT_GE(timer.endTicks, timer.beginTicks) << timer.name;
        EXPECT_GE(timer.milliseconds, 0.0) << timer.name;
    }
    // Nested regions lie inside the one around them.
    EXPECT_LE(timers[0].beginTicks, timers[1].beginTicks);
    EXPECT_GE(timers[0].endTicks, timers[2].endTicks);
    EXPECT_LE(timers[1].endTicks, timers[2].beginTicks);
    EXPECT_EQ(readBack<uint32_t>(*target), pattern);
}

// A recording of many frames (a test or the bench converging a scene in one list) times more
// regions than one D3D12 query heap or Vulkan query pool holds: every region comes back, in order.
TEST_P(TimerTest, ARecordingTimesMoreRegionsThanOneQueryHeapHolds) {
    constexpr uint32_t kRegions = 1300; // over two heaps of 512 regions
    rhi::BufferHandle data =
        device().createBuffer({.size = 256, .usage = rhi::BufferUsage::Storage, .debugName = "timed fills"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    for (uint32_t region = 0; region < kRegions; ++region) {
        list->beginTimer("fill " + std::to_string(region));
        list->fillBuffer(*data, region);
        list->endTimer();
    }
    list->end();
    submitAndWait(*list);
    const std::vector<rhi::TimerResult> timers = list->timerResults();
    ASSERT_EQ(timers.size(), kRegions);
    for (uint32_t region = 0; region < kRegions; ++region) {
        SCOPED_TRACE(region);
        EXPECT_EQ(timers[region].name, "fill " + std::to_string(region));
        EXPECT_GT(timers[region].beginTicks, 0u);
        EXPECT_LE(timers[region].beginTicks, timers[region].endTicks);
        if (region > 0) {
            EXPECT_LE(timers[region - 1].endTicks, timers[region].beginTicks);
        }
    }
}

TEST_P(TimerTest, UnbalancedMarkersAndTimersThrow) {
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    EXPECT_THROW(list->endTimer(), rhi::Error);
    EXPECT_THROW(list->endMarker(), rhi::Error);
    list->beginTimer("open");
    EXPECT_THROW(list->endMarker(), rhi::Error);
    EXPECT_THROW(list->end(), rhi::Error);
    list->endTimer();
    list->end();
    submitAndWait(*list);
}

LUMINA_INSTANTIATE_GPU_TEST(TimerTest);

} // namespace
} // namespace lumina::test
