// The compute queue waits on the graphics queue (waitForQueue) and reads what it wrote.
#include "shaders/common/constants_shared.h"
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <iostream>

namespace lumina::test {
namespace {

using AsyncComputeTest = GpuTest;
using gpu::ChainConstants;

TEST_P(AsyncComputeTest, ComputeQueueReadsWhatTheGraphicsQueueWrote) {
    LUMINA_REQUIRE_KERNELS();
    constexpr uint32_t kCount = 2048, kGroupSize = LUMINA_LINEAR_GROUP_SIZE;
    const ComputeKernel seed =
        loadComputeKernel("rhi_tests/chain_seed", {{rhi::BindingType::BufferUAV, 0}}, sizeof(ChainConstants));
    const ComputeKernel step = loadComputeKernel(
        "rhi_tests/chain_step", {{rhi::BindingType::BufferSRV, 0}, {rhi::BindingType::BufferUAV, 0}},
        sizeof(ChainConstants));
    const auto makeBuffer = [&](const char* name) {
        return device().createBuffer({.size = kCount * 4,
                                      .structStride = 4,
                                      .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                      .debugName = name});
    };
    rhi::BufferHandle produced = makeBuffer("written on graphics");
    rhi::BufferHandle consumed = makeBuffer("written on compute");

    rhi::CommandListHandle graphicsList = device().createCommandList(rhi::QueueType::Graphics);
    graphicsList->begin();
    graphicsList->setComputeState(
        {.pipeline = seed.pipeline,
         .bindings = {{seed.layout, {rhi::BindingSetItem::rwStructuredBuffer(0, produced)}}}});
    graphicsList->pushConstants(ChainConstants{kCount, 3, 11, 0});
    graphicsList->dispatch(kCount / kGroupSize);
    graphicsList->end();

    rhi::CommandListHandle computeList = device().createCommandList(rhi::QueueType::Compute);
    EXPECT_EQ(computeList->queueType(), rhi::QueueType::Compute);
    computeList->begin();
    computeList->setComputeState({.pipeline = step.pipeline,
                                  .bindings = {{step.layout,
                                                {rhi::BindingSetItem::structuredBuffer(0, produced),
                                                 rhi::BindingSetItem::rwStructuredBuffer(0, consumed)}}}});
    computeList->pushConstants(ChainConstants{kCount, 2, 1, 0});
    computeList->dispatch(kCount / kGroupSize);
    computeList->end();

    rhi::IQueue& graphics = device().queue(rhi::QueueType::Graphics);
    rhi::IQueue& compute = device().queue(rhi::QueueType::Compute);
    const uint64_t produceDone = graphics.submit(*graphicsList);
    compute.waitForQueue(graphics, produceDone);
    const uint64_t consumeDone = compute.submit(*computeList);
    compute.waitForValue(consumeDone);
    EXPECT_GE(graphics.completedValue(), produceDone);
    // The graphics queue reads the compute queue's result back after waiting for it too.
    graphics.waitForQueue(compute, consumeDone);

    const std::vector<uint32_t> result = readBack<uint32_t>(*consumed);
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(result[i], 2 * (3 * i + 11) + 1) << "element " << i;
    }
    std::cout << "[ info ] separate compute queue: " << std::boolalpha
              << device().capabilities().separateComputeQueue << '\n';
}

TEST_P(AsyncComputeTest, CopyAndComputeQueuesHandBuffersOverWithoutKernels) {
    constexpr uint32_t kCount = 1024;
    std::vector<uint32_t> values(kCount);
    for (uint32_t i = 0; i < kCount; ++i) {
        values[i] = i * 2654435761u;
    }
    rhi::BufferHandle uploaded =
        device().createBuffer({.size = kCount * 4, .debugName = "written on the copy queue"});
    rhi::BufferHandle copied =
        device().createBuffer({.size = kCount * 4, .debugName = "copied on the compute queue"});
    rhi::CommandListHandle copyList = device().createCommandList(rhi::QueueType::Copy);
    copyList->begin();
    copyList->writeBuffer(*uploaded, values.data(), kCount * 4);
    copyList->end();
    rhi::CommandListHandle computeList = device().createCommandList(rhi::QueueType::Compute);
    computeList->begin();
    computeList->copyBuffer(*copied, 0, *uploaded, 0, kCount * 4);
    computeList->end();

    rhi::IQueue& copy = device().queue(rhi::QueueType::Copy);
    rhi::IQueue& compute = device().queue(rhi::QueueType::Compute);
    const uint64_t uploadDone = copy.submit(*copyList);
    compute.waitForQueue(copy, uploadDone);
    const uint64_t copyDone = compute.submit(*computeList);
    device().queue(rhi::QueueType::Graphics).waitForQueue(compute, copyDone);
    compute.waitForValue(copyDone);
    EXPECT_EQ(readBack<uint32_t>(*copied), values);
}

TEST_P(AsyncComputeTest, WaitingForAValueNeverSubmittedThrows) {
    rhi::IQueue& graphics = device().queue(rhi::QueueType::Graphics);
    rhi::IQueue& compute = device().queue(rhi::QueueType::Compute);
    EXPECT_THROW(compute.waitForQueue(graphics, graphics.completedValue() + 100), rhi::Error);
    EXPECT_THROW(graphics.waitForValue(100), rhi::Error);
}

LUMINA_INSTANTIATE_GPU_TEST(AsyncComputeTest);

} // namespace
} // namespace lumina::test
