// THE DELIBERATE-ERROR TEST: with automatic barriers off, a dispatch writes a buffer and the
// next one reads it with no barrier in between. Synchronization validation must catch it.
// If this test fails, the other GPU tests' "no validation messages" proves nothing.
#include "shaders/common/constants_shared.h"
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

namespace lumina::test {
namespace {

using SynchronizationValidationTest = GpuTest;
using gpu::ChainConstants;

constexpr uint32_t kCount = 256, kGroupSize = LUMINA_LINEAR_GROUP_SIZE;

TEST_P(SynchronizationValidationTest, MissingBarrierBetweenDispatchesIsReported) {
    if (GetParam() == rhi::Api::D3D12) {
        GTEST_SKIP() << "the D3D12 debug layer has no synchronization validation: a missing UAV barrier "
                        "goes unreported";
    }
    LUMINA_REQUIRE_KERNELS();
    expectValidationMessages();
    // The second dispatch reads through an SRV what the first wrote through a UAV. (A
    // read-modify-write of one UAV twice would be a hazard too, but the Debian 12 validation
    // layer, 1.3.239, does not flag storage write after storage write in the same stage.)
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
    rhi::BufferHandle written = makeBuffer("written, then read without a barrier");
    rhi::BufferHandle result = makeBuffer("result");

    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->setAutomaticBarriers(false);
    list->transition(*written, rhi::ResourceState::UnorderedAccess);
    list->transition(*result, rhi::ResourceState::UnorderedAccess);
    list->commitBarriers();
    list->setComputeState(
        {.pipeline = seed.pipeline,
         .bindings = {{seed.layout, {rhi::BindingSetItem::rwStructuredBuffer(0, written)}}}});
    list->pushConstants(ChainConstants{kCount, 1, 0, 0});
    list->dispatch(kCount / kGroupSize); // writes `written`
    // Missing here: transition(*written, ShaderResource) + commitBarriers().
    list->setComputeState({.pipeline = step.pipeline,
                           .bindings = {{step.layout,
                                         {rhi::BindingSetItem::structuredBuffer(0, written),
                                          rhi::BindingSetItem::rwStructuredBuffer(0, result)}}}});
    list->dispatch(kCount / kGroupSize); // reads it
    list->end();
    submitAndWait(*list);
    device().waitIdle();

    const std::vector<std::string> messages = validationMessages();
    size_t hazards = 0;
    for (const std::string& message : messages) {
        hazards += message.find("SYNC-HAZARD-READ-AFTER-WRITE") != std::string::npos;
    }
    EXPECT_GE(hazards, 1u) << "synchronization validation missed a read-after-write between dispatches ("
                           << messages.size() << " other messages)";
}

TEST_P(SynchronizationValidationTest, ExplicitUavBarrierSilencesIt) {
    LUMINA_REQUIRE_KERNELS();
    LUMINA_REQUIRE_KERNEL("rhi_tests/accumulate");
    const ComputeKernel kernel = loadComputeKernel(
        "rhi_tests/accumulate", {{rhi::BindingType::RawBufferUAV, 0}}, sizeof(ChainConstants));
    rhi::BufferHandle data =
        device().createBuffer({.size = kCount * 4,
                               .usage = rhi::BufferUsage::Raw | rhi::BufferUsage::Storage,
                               .debugName = "ordered buffer"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->setAutomaticBarriers(false);
    list->transition(*data, rhi::ResourceState::CopyDest);
    list->commitBarriers();
    list->fillBuffer(*data, 5);
    list->transition(*data, rhi::ResourceState::UnorderedAccess);
    list->setComputeState({.pipeline = kernel.pipeline,
                           .bindings = {{kernel.layout, {rhi::BindingSetItem::rwRawBuffer(0, data)}}}});
    list->pushConstants(ChainConstants{kCount, 0, 1, 0});
    list->dispatch(kCount / kGroupSize); // the pending transition is recorded first
    list->uavBarrier(*data);
    list->commitBarriers();
    list->dispatch(kCount / kGroupSize);
    list->transition(*data, rhi::ResourceState::CopySource);
    list->end();
    submitAndWait(*list);
    const std::vector<uint32_t> result = readBack<uint32_t>(*data);
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(result[i], 5 + 2 * (1 + i)) << "element " << i;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(SynchronizationValidationTest);

} // namespace
} // namespace lumina::test
