// Compute: every binding kind in one kernel, barrier chains across passes, UAV -> UAV chains
// on one buffer, indirect dispatch, and the state tracker's SRV + UAV conflict.
#include "shaders/common/constants_shared.h"
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/rhi/texel_patterns.h"

#include <numeric>

namespace lumina::test {
namespace {

using ComputeTest = GpuTest;
using gpu::ChainConstants;

constexpr uint32_t kGroupSize = LUMINA_LINEAR_GROUP_SIZE; // numthreads of the chain kernels
uint32_t groupsFor(uint32_t count) {
    return (count + kGroupSize - 1) / kGroupSize;
}

class ChainTest : public ComputeTest {
protected:
    void SetUp() override {
        ComputeTest::SetUp();
        LUMINA_REQUIRE_KERNELS();
        seed = loadComputeKernel("rhi_tests/chain_seed", {{rhi::BindingType::BufferUAV, 0}},
                                 sizeof(ChainConstants));
        step = loadComputeKernel("rhi_tests/chain_step",
                                 {{rhi::BindingType::BufferSRV, 0}, {rhi::BindingType::BufferUAV, 0}},
                                 sizeof(ChainConstants));
        // Tests that bind it start with LUMINA_REQUIRE_KERNEL(kAccumulate): the DXBC build has none.
        if (kernelUnavailable(kAccumulate).empty()) {
            accumulate =
                loadComputeKernel(kAccumulate, {{rhi::BindingType::RawBufferUAV, 0}}, sizeof(ChainConstants));
        }
    }

    static constexpr const char* kAccumulate = "rhi_tests/accumulate";

    rhi::BufferHandle uintBuffer(uint32_t count, const std::string& name) {
        return device().createBuffer(
            {.size = count * 4u,
             .structStride = 4,
             .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Raw | rhi::BufferUsage::Storage,
             .debugName = name});
    }

    void runSeed(rhi::ICommandList& list, rhi::BufferHandle out, ChainConstants constants) {
        list.setComputeState(
            {.pipeline = seed.pipeline,
             .bindings = {{seed.layout, {rhi::BindingSetItem::rwStructuredBuffer(0, out)}}}});
        list.pushConstants(constants);
        list.dispatch(groupsFor(constants.count));
    }

    void runStep(rhi::ICommandList& list, rhi::BufferHandle in, rhi::BufferHandle out,
                 ChainConstants constants) {
        list.setComputeState({.pipeline = step.pipeline,
                              .bindings = {{step.layout,
                                            {rhi::BindingSetItem::structuredBuffer(0, in),
                                             rhi::BindingSetItem::rwStructuredBuffer(0, out)}}}});
        list.pushConstants(constants);
        list.dispatch(groupsFor(constants.count));
    }

    void bindAccumulate(rhi::ICommandList& list, rhi::BufferHandle data) {
        list.setComputeState(
            {.pipeline = accumulate.pipeline,
             .bindings = {{accumulate.layout, {rhi::BindingSetItem::rwRawBuffer(0, data)}}}});
    }

    ComputeKernel seed, step, accumulate;
};

TEST_P(ComputeTest, WritePatternUsesEveryBindingKind) {
    LUMINA_REQUIRE_KERNELS();
    using gpu::PatternElement;
    using gpu::WritePatternConstants;
    using gpu::WritePatternPush;
    constexpr uint32_t kCount = 100, kWidth = 8, kHeight = 6;
    const WritePatternPush push{kCount, 1234, kWidth, kHeight};
    const WritePatternConstants constants{
        .multiplier = {2, 3, 4, 5}, .elementScale = 0.5f, .texelW = 0.25f, .pad0 = 0.0f, .pad1 = 0.0f};
    std::vector<PatternElement> input(kCount);
    for (uint32_t i = 0; i < kCount; ++i) {
        input[i].a = {i, i + 1, i * 2, 9};
        input[i].b = {0, 0, 0, float(i) + 0.5f};
    }

    const ComputeKernel kernel = loadComputeKernel("rhi_tests/write_pattern",
                                                   {{rhi::BindingType::ConstantBuffer, 0},
                                                    {rhi::BindingType::BufferSRV, 0},
                                                    {rhi::BindingType::BufferUAV, 0},
                                                    {rhi::BindingType::RawBufferUAV, 1},
                                                    {rhi::BindingType::TextureUAV, 2}},
                                                   sizeof(WritePatternPush));
    // The constant buffer sits at an offset inside a larger buffer, the input is one range of
    // a buffer too: ranges are part of what is tested.
    constexpr uint64_t kConstantOffset = 256;
    rhi::BufferHandle constantBuffer = device().createBuffer(
        {.size = 512, .usage = rhi::BufferUsage::Constant, .debugName = "pattern constants"});
    rhi::BufferHandle inputBuffer = device().createBuffer({.size = (kCount + 2) * sizeof(PatternElement),
                                                           .structStride = sizeof(PatternElement),
                                                           .usage = rhi::BufferUsage::Structured,
                                                           .debugName = "pattern input"});
    rhi::BufferHandle structured =
        device().createBuffer({.size = kCount * sizeof(PatternElement),
                               .structStride = sizeof(PatternElement),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "pattern structured"});
    rhi::BufferHandle raw = device().createBuffer({.size = kCount * 4,
                                                   .usage = rhi::BufferUsage::Raw | rhi::BufferUsage::Storage,
                                                   .debugName = "pattern raw"});
    rhi::TextureHandle image = device().createTexture({.format = rhi::Format::RGBA16_FLOAT,
                                                       .width = kWidth,
                                                       .height = kHeight,
                                                       .usage = rhi::TextureUsage::Storage,
                                                       .debugName = "pattern image"});

    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->writeBuffer(*constantBuffer, &constants, sizeof(constants), kConstantOffset);
    // Elements 1..kCount of the input buffer are the input: bound with a range offset.
    list->writeBuffer(*inputBuffer, input.data(), input.size() * sizeof(PatternElement),
                      sizeof(PatternElement));
    list->setComputeState(
        {.pipeline = kernel.pipeline,
         .bindings = {
             {kernel.layout,
              {rhi::BindingSetItem::constantBuffer(0, constantBuffer, {kConstantOffset, sizeof(constants)}),
               rhi::BindingSetItem::structuredBuffer(
                   0, inputBuffer, {sizeof(PatternElement), kCount * sizeof(PatternElement)}),
               rhi::BindingSetItem::rwStructuredBuffer(0, structured),
               rhi::BindingSetItem::rwRawBuffer(1, raw), rhi::BindingSetItem::storageTexture(2, image)}}}});
    list->pushConstants(push);
    list->dispatch(groupsFor(kCount));
    list->end();
    submitAndWait(*list);

    const std::vector<PatternElement> elements = readBack<PatternElement>(*structured);
    const std::vector<uint32_t> words = readBack<uint32_t>(*raw);
    for (uint32_t i = 0; i < kCount; ++i) {
        SCOPED_TRACE("element " + std::to_string(i));
        EXPECT_EQ(elements[i].a.x, input[i].a.x * 2 + push.seed);
        EXPECT_EQ(elements[i].a.y, input[i].a.y * 3 + i);
        EXPECT_EQ(elements[i].a.z, input[i].a.z * 4 + 7);
        EXPECT_EQ(elements[i].a.w, input[i].a.w * 5 + 1);
        EXPECT_EQ(elements[i].b.x, float(i));
        EXPECT_EQ(elements[i].b.y, float(push.seed));
        EXPECT_EQ(elements[i].b.z, float(i) * 0.5f);
        EXPECT_EQ(elements[i].b.w, input[i].b.w);
        EXPECT_EQ(words[i], i * 7 + push.seed);
    }
    const std::vector<uint8_t> texels = rhi::readTexture(device(), *image);
    const auto* halves = reinterpret_cast<const uint16_t*>(texels.data());
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const uint16_t* texel = halves + (y * kWidth + x) * 4;
            ASSERT_EQ(halfToFloat(texel[0]), float(x)) << "texel " << x << "," << y;
            ASSERT_EQ(halfToFloat(texel[1]), float(y)) << "texel " << x << "," << y;
            ASSERT_EQ(halfToFloat(texel[2]), float(push.seed)) << "texel " << x << "," << y;
            ASSERT_EQ(halfToFloat(texel[3]), 0.25f) << "texel " << x << "," << y;
        }
    }
}

using BarrierChainTest = ChainTest;

TEST_P(BarrierChainTest, EachPassReadsWhatThePreviousOneWrote) {
    constexpr uint32_t kCount = 1000;
    rhi::BufferHandle a = uintBuffer(kCount, "chain A");
    rhi::BufferHandle b = uintBuffer(kCount, "chain B");
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    runSeed(*list, a, {kCount, 3, 1, 0});    // A = 3i + 1
    runStep(*list, a, b, {kCount, 2, 5, 0}); // B = 2A + 5
    runStep(*list, b, a, {kCount, 3, 7, 0}); // A = 3B + 7, back into A's buffer
    list->end();
    submitAndWait(*list);

    const std::vector<uint32_t> resultA = readBack<uint32_t>(*a);
    const std::vector<uint32_t> resultB = readBack<uint32_t>(*b);
    for (uint32_t i = 0; i < kCount; ++i) {
        const uint32_t seeded = 3 * i + 1;
        ASSERT_EQ(resultB[i], 2 * seeded + 5) << "element " << i;
        ASSERT_EQ(resultA[i], 3 * (2 * seeded + 5) + 7) << "element " << i;
    }
}

TEST_P(BarrierChainTest, ChainsContinueAcrossCommandLists) {
    LUMINA_REQUIRE_KERNEL(kAccumulate);
    constexpr uint32_t kCount = 300;
    rhi::BufferHandle a = uintBuffer(kCount, "chain A");
    rhi::BufferHandle b = uintBuffer(kCount, "chain B");
    rhi::CommandListHandle first = device().createCommandList();
    rhi::CommandListHandle second = device().createCommandList();
    first->begin();
    runSeed(*first, a, {kCount, 1, 0, 0}); // A = i
    first->end();
    second->begin();
    runStep(*second, a, b, {kCount, 5, 1, 0}); // B = 5A + 1
    bindAccumulate(*second, b);
    second->pushConstants(ChainConstants{kCount, 0, 10, 0}); // B += 10 + i
    second->dispatch(groupsFor(kCount));
    second->end();
    rhi::ICommandList* lists[] = {first.get(), second.get()};
    rhi::IQueue& queue = device().queue(rhi::QueueType::Graphics);
    queue.waitForValue(queue.submit(lists));

    const std::vector<uint32_t> result = readBack<uint32_t>(*b);
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(result[i], 5 * i + 1 + 10 + i) << "element " << i;
    }
}

using UavChainTest = ChainTest;

TEST_P(UavChainTest, EachDispatchAddsToThePreviousResult) {
    LUMINA_REQUIRE_KERNEL(kAccumulate);
    constexpr uint32_t kCount = 777, kDispatches = 8;
    std::vector<uint32_t> expected(kCount);
    std::iota(expected.begin(), expected.end(), 100u);
    rhi::BufferHandle data = uintBuffer(kCount, "accumulated");
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->writeBuffer(*data, expected.data(), kCount * 4);
    bindAccumulate(*list, data);
    for (uint32_t pass = 0; pass < kDispatches; ++pass) {
        const uint32_t addend = pass * 1000 + 1;
        list->pushConstants(ChainConstants{kCount, 0, addend, 0});
        list->dispatch(groupsFor(kCount));
        for (uint32_t i = 0; i < kCount; ++i) {
            expected[i] += addend + i;
        }
    }
    list->end();
    submitAndWait(*list);
    EXPECT_EQ(readBack<uint32_t>(*data), expected);
}

TEST_P(UavChainTest, DispatchIndirectReadsItsArgumentsFromAWrittenBuffer) {
    constexpr uint32_t kCount = 200;
    rhi::BufferHandle out = uintBuffer(kCount, "indirect output");
    rhi::BufferHandle args = device().createBuffer(
        {.size = 16, .usage = rhi::BufferUsage::Indirect, .debugName = "indirect args"});
    const uint32_t groups[4] = {groupsFor(kCount), 1, 1, 0};
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*out, 0);
    list->writeBuffer(*args, groups, sizeof(groups));
    list->setComputeState({.pipeline = seed.pipeline,
                           .bindings = {{seed.layout, {rhi::BindingSetItem::rwStructuredBuffer(0, out)}}}});
    list->pushConstants(ChainConstants{kCount, 4, 2, 0});
    list->dispatchIndirect(*args, 0);
    list->end();
    submitAndWait(*list);
    const std::vector<uint32_t> result = readBack<uint32_t>(*out);
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(result[i], 4 * i + 2) << "element " << i;
    }
}

TEST_P(BarrierChainTest, TrackerRejectsOneBufferAsBothSrvAndUavInOneDispatch) {
    constexpr uint32_t kCount = 64;
    rhi::BufferHandle both = uintBuffer(kCount, "read and written");
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*both, 1);
    runSeed(*list, both, {kCount, 1, 0, 0});
    try {
        runStep(*list, both, both, {kCount, 1, 1, 0});
        ADD_FAILURE() << "binding one buffer as SRV and UAV of one dispatch did not throw";
    } catch (const rhi::Error& error) {
        EXPECT_NE(std::string(error.what()).find("read and written"), std::string::npos) << error.what();
    }
    // The list stays consistent: it still ends, submits and runs what was recorded.
    list->end();
    submitAndWait(*list);
    const std::vector<uint32_t> result = readBack<uint32_t>(*both);
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(result[i], i) << "element " << i;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(ComputeTest);
LUMINA_INSTANTIATE_GPU_TEST(BarrierChainTest);
LUMINA_INSTANTIATE_GPU_TEST(UavChainTest);

} // namespace
} // namespace lumina::test
