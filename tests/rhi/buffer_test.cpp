// Buffer round trips through every memory type, at offsets, and memory accounting.
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace lumina::test {
namespace {

using BufferTest = GpuTest;

std::vector<uint32_t> sequence(size_t count, uint32_t first) {
    std::vector<uint32_t> values(count);
    std::iota(values.begin(), values.end(), first);
    return values;
}

TEST_P(BufferTest, GpuOnlyRoundTripThroughWriteAndReadBuffer) {
    const std::vector<uint32_t> values = sequence(1000, 17);
    rhi::BufferHandle buffer = rhi::createBufferWithData(
        device(), {.structStride = 4, .usage = rhi::BufferUsage::Structured, .debugName = "gpu-only"},
        values.data(), values.size() * sizeof(uint32_t));
    EXPECT_EQ(buffer->desc().size, values.size() * sizeof(uint32_t));
    EXPECT_EQ(readBack<uint32_t>(*buffer), values);
}

TEST_P(BufferTest, WriteBufferAtOffsets) {
    rhi::BufferHandle buffer = device().createBuffer({.size = 4096, .debugName = "offsets"});
    const uint32_t a = 0x11111111, b = 0x22222222;
    const std::vector<uint32_t> block = sequence(64, 1000);
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*buffer, 0);
    list->writeBuffer(*buffer, &a, sizeof(a), 4);
    list->writeBuffer(*buffer, &b, sizeof(b), 4092);
    list->writeBuffer(*buffer, block.data(), block.size() * 4, 1024);
    list->writeBuffer(*buffer, &b, sizeof(b), 8); // a second write in the same state
    list->end();
    submitAndWait(*list);

    std::vector<uint32_t> expected(1024, 0);
    expected[1] = a;
    expected[2] = b;
    expected[1023] = b;
    std::copy(block.begin(), block.end(), expected.begin() + 256);
    EXPECT_EQ(readBack<uint32_t>(*buffer), expected);
}

TEST_P(BufferTest, UploadBufferIsMappedAndCopiesToTheGpu) {
    const std::vector<uint32_t> values = sequence(256, 5);
    rhi::BufferHandle upload =
        device().createBuffer({.size = 1024, .memory = rhi::MemoryType::Upload, .debugName = "upload"});
    std::memcpy(upload->map(), values.data(), 1024);
    rhi::BufferHandle target = device().createBuffer({.size = 2048, .debugName = "target"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*target, 0xFFFFFFFF);
    list->copyBuffer(*target, 512, *upload, 256, 512); // values[64..192) to words 128..256
    list->end();
    submitAndWait(*list);

    const std::vector<uint32_t> result = readBack<uint32_t>(*target);
    for (size_t word = 0; word < result.size(); ++word) {
        const bool copied = word >= 128 && word < 256;
        ASSERT_EQ(result[word], copied ? values[word - 128 + 64] : 0xFFFFFFFF) << "word " << word;
    }
}

TEST_P(BufferTest, ReadbackBufferReceivesCopiesAtOffsets) {
    const std::vector<uint32_t> values = sequence(128, 900);
    rhi::BufferHandle source =
        rhi::createBufferWithData(device(), {.debugName = "source"}, values.data(), 512);
    rhi::BufferHandle readback =
        device().createBuffer({.size = 1024, .memory = rhi::MemoryType::Readback, .debugName = "readback"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*readback, 0);
    list->copyBuffer(*readback, 64, *source, 0, 512);
    list->end();
    submitAndWait(*list);

    const auto* mapped = static_cast<const uint32_t*>(readback->map());
    for (size_t word = 0; word < 256; ++word) {
        const bool copied = word >= 16 && word < 16 + 128;
        ASSERT_EQ(mapped[word], copied ? values[word - 16] : 0u) << "word " << word;
    }
}

TEST_P(BufferTest, SameStateWritesInSuccessiveListsStayOrdered) {
    // Both lists leave the buffer in CopyDest: no transition orders the second write after
    // the first, only the backend's guarantee that a list sees all earlier lists' writes.
    rhi::BufferHandle buffer = device().createBuffer({.size = 256, .debugName = "written by two lists"});
    const std::vector<uint32_t> first(64, 1), second(32, 2);
    rhi::CommandListHandle a = device().createCommandList();
    rhi::CommandListHandle b = device().createCommandList();
    a->begin();
    a->fillBuffer(*buffer, 0);
    a->writeBuffer(*buffer, first.data(), 256);
    a->end();
    b->begin();
    b->writeBuffer(*buffer, second.data(), 128, 64);
    b->end();
    rhi::ICommandList* lists[] = {a.get(), b.get()};
    rhi::IQueue& queue = device().queue(rhi::QueueType::Graphics);
    queue.waitForValue(queue.submit(lists));

    std::vector<uint32_t> expected(64, 1);
    std::fill(expected.begin() + 16, expected.begin() + 48, 2u);
    EXPECT_EQ(readBack<uint32_t>(*buffer), expected);
}

TEST_P(BufferTest, FillBufferWritesEveryWord) {
    rhi::BufferHandle buffer = device().createBuffer({.size = 4000, .debugName = "fill"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->fillBuffer(*buffer, 0xDEADBEEF);
    list->end();
    submitAndWait(*list);
    EXPECT_EQ(readBack<uint32_t>(*buffer), std::vector<uint32_t>(1000, 0xDEADBEEF));
}

// Beyond 8 MiB the D3D12 backend fills by copies (one UAV clear there is one dispatch over the
// whole buffer, past Vulkan's 65535 groups under vkd3d); the size is no multiple of its 1 MiB
// chunks, and the buffer is then filled again with another value.
TEST_P(BufferTest, FillBufferWritesEveryWordOfABufferOver8MiB) {
    const size_t words = (24u << 20) / 4 + 5;
    rhi::BufferHandle buffer = device().createBuffer({.size = words * 4, .debugName = "large fill"});
    for (const uint32_t value : {0x01234567u, 0u}) {
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        list->fillBuffer(*buffer, value);
        list->end();
        submitAndWait(*list);
        const std::vector<uint32_t> result = readBack<uint32_t>(*buffer);
        ASSERT_EQ(result.size(), words);
        const auto wrong = std::find_if(result.begin(), result.end(), [&](uint32_t w) { return w != value; });
        EXPECT_EQ(wrong, result.end())
            << "word " << (wrong - result.begin()) << " of " << words << " is not " << value;
    }
}

TEST_P(BufferTest, LargeWritesGrowTheUploadMemoryAndListsAreReusable) {
    const size_t words = 3 * 1024 * 1024 / 4; // more than one upload chunk
    rhi::BufferHandle buffer = device().createBuffer({.size = words * 4, .debugName = "large"});
    rhi::CommandListHandle list = device().createCommandList();
    for (uint32_t round = 0; round < 3; ++round) {
        const std::vector<uint32_t> values = sequence(words, round * 7);
        list->begin(); // waits for the previous round and recycles its upload memory
        list->writeBuffer(*buffer, values.data(), values.size() * 4 / 2);
        list->writeBuffer(*buffer, values.data() + words / 2, values.size() * 4 / 2, values.size() * 4 / 2);
        list->end();
        submitAndWait(*list);
        ASSERT_EQ(readBack<uint32_t>(*buffer), values) << "round " << round;
    }
}

TEST_P(BufferTest, AllocatedMemoryIsTracked) {
    const uint64_t before = device().allocatedMemoryBytes();
    {
        rhi::BufferHandle buffer = device().createBuffer({.size = 1 << 20, .debugName = "accounted"});
        EXPECT_GE(device().allocatedMemoryBytes(), before + (1 << 20));
    }
    EXPECT_EQ(device().allocatedMemoryBytes(), before);
}

TEST_P(BufferTest, MappingGpuOnlyMemoryThrows) {
    rhi::BufferHandle buffer = device().createBuffer({.size = 16, .debugName = "not mappable"});
    EXPECT_THROW(buffer->map(), rhi::Error);
}

TEST_P(BufferTest, CopiesOutsideTheBufferThrowWithItsName) {
    rhi::BufferHandle small = device().createBuffer({.size = 16, .debugName = "small buffer"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    const uint32_t data[8] = {};
    try {
        list->writeBuffer(*small, data, sizeof(data), 0);
        ADD_FAILURE() << "writeBuffer past the end did not throw";
    } catch (const rhi::Error& error) {
        EXPECT_NE(std::string(error.what()).find("small buffer"), std::string::npos) << error.what();
    }
    list->end();
}

LUMINA_INSTANTIATE_GPU_TEST(BufferTest);

} // namespace
} // namespace lumina::test
