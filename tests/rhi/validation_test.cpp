// The backend-neutral rules of rhi/validation.h, each broken once through every backend: the
// same call must be refused with the same message on Vulkan and D3D12, including the rules
// only one API needs (512-byte copy offsets and 256-byte row pitches come from D3D12, and
// Vulkan alone would accept the texel size).
#include "rhi/validation.h"
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <functional>
#include <initializer_list>
#include <string>

namespace lumina::test {
namespace {

using ValidationTest = GpuTest;

// `call` throws rhi::Error whose message holds every one of `words`.
void expectRefused(const std::function<void()>& call, std::initializer_list<const char*> words) {
    try {
        call();
        ADD_FAILURE() << "not refused; expected an error naming '" << *words.begin() << "'";
    } catch (const rhi::Error& error) {
        const std::string message = error.what();
        for (const char* word : words) {
            EXPECT_NE(message.find(word), std::string::npos) << "'" << word << "' missing from: " << message;
        }
    }
}

rhi::TextureDesc smallTexture(const char* name, rhi::Format format = rhi::Format::RGBA8_UNORM) {
    return {
        .format = format, .width = 8, .height = 4, .usage = rhi::TextureUsage::Sampled, .debugName = name};
}

TEST_P(ValidationTest, BufferDescriptionsFollowOneRuleOnEveryBackend) {
    expectRefused([&] { device().createBuffer({.size = 0, .debugName = "empty"}); }, {"empty", "size is 0"});
    expectRefused(
        [&] {
            device().createBuffer(
                {.size = 64, .usage = rhi::BufferUsage::Structured, .debugName = "no stride"});
        },
        {"no stride", "structStride"});
    for (rhi::MemoryType memory : {rhi::MemoryType::Upload, rhi::MemoryType::Readback}) {
        expectRefused(
            [&] {
                device().createBuffer({.size = 64,
                                       .usage = rhi::BufferUsage::Raw | rhi::BufferUsage::Storage,
                                       .memory = memory,
                                       .debugName = "host storage"});
            },
            {"host storage", "Storage usage needs GpuOnly", rhi::memoryTypeName(memory)});
    }
}

TEST_P(ValidationTest, TextureDescriptionsFollowOneRuleOnEveryBackend) {
    using D = rhi::TextureDimension;
    using U = rhi::TextureUsage;
    // Each was refused by one backend only before the rules moved to rhi/validation.h.
    expectRefused(
        [&] {
            device().createTexture({.width = 4, .height = 4, .arrayLayers = 2, .debugName = "two layers"});
        },
        {"two layers", "Texture2D has one layer"});
    expectRefused(
        [&] {
            device().createTexture({.dimension = D::TextureCube,
                                    .width = 4,
                                    .height = 4,
                                    .arrayLayers = 12,
                                    .debugName = "two cubes"});
        },
        {"two cubes", "exactly 6 layers"});
    expectRefused(
        [&] {
            device().createTexture({.format = rhi::Format::RGBA8_SRGB,
                                    .width = 4,
                                    .height = 4,
                                    .usage = U::Sampled | U::Storage,
                                    .debugName = "srgb storage"});
        },
        {"srgb storage", "sRGB"});
    expectRefused(
        [&] {
            device().createTexture({.dimension = D::Texture3D,
                                    .format = rhi::Format::D32_FLOAT,
                                    .width = 4,
                                    .height = 4,
                                    .depth = 4,
                                    .usage = U::DepthStencil,
                                    .debugName = "depth volume"});
        },
        {"depth volume", "2D depth format"});
    expectRefused(
        [&] { device().createTexture({.width = 4, .height = 4, .mipLevels = 4, .debugName = "deep chain"}); },
        {"deep chain", "4 mips", "at most 3"});
}

TEST_P(ValidationTest, SamplerAnisotropyFollowsOneRuleOnEveryBackend) {
    // D3D12 refused these; Vulkan clamped them to its device limit.
    expectRefused([&] { device().createSampler({.maxAnisotropy = 32.0f, .debugName = "too sharp"}); },
                  {"too sharp", "maxAnisotropy 32", "[1, 16]"});
    expectRefused([&] { device().createSampler({.maxAnisotropy = 0.5f, .debugName = "below one"}); },
                  {"below one", "maxAnisotropy 0.5"});
}

TEST_P(ValidationTest, BufferTextureCopiesNeedD3D12AlignmentsOnEveryBackend) {
    rhi::TextureHandle texture = device().createTexture(smallTexture("copied texture"));
    rhi::BufferHandle buffer = device().createBuffer(
        {.size = 4096, .memory = rhi::MemoryType::Readback, .debugName = "copy buffer"});
    const uint32_t pitch = rhi::kTextureCopyRowAlignment;
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    // A multiple of the texel size and of 4 (all Vulkan asks), not of 512.
    expectRefused([&] { list->copyTextureToBuffer(*buffer, 256, pitch, *texture, {}); },
                  {"copyTextureToBuffer", "copied texture", "copy buffer", "offset 256", "512"});
    expectRefused([&] { list->copyBufferToTexture(*texture, {}, *buffer, 256, pitch); },
                  {"copyBufferToTexture", "offset 256", "512"});
    // The packed row (8 texels x 4 bytes), which Vulkan would take, is not a multiple of 256.
    expectRefused([&] { list->copyTextureToBuffer(*buffer, 0, 32, *texture, {}); },
                  {"row pitch 32", "multiple of 256"});
    expectRefused([&] { list->copyTextureToBuffer(*buffer, 3584, pitch, *texture, {}); },
                  {"4 rows of 256 bytes at offset 3584", "4096 bytes"});
    expectRefused([&] { list->copyTextureToBuffer(*buffer, 0, pitch, *texture, {.mipLevel = 1}); },
                  {"mip 1", "does not exist"});
    list->end();
}

TEST_P(ValidationTest, ACopyThatKeepsTheRulesArrivesAtTheAlignedOffset) {
    rhi::TextureHandle texture = device().createTexture(smallTexture("pattern"));
    std::vector<uint32_t> texels(8 * 4);
    for (size_t i = 0; i < texels.size(); ++i) {
        texels[i] = 0x01020304u * uint32_t(i + 1);
    }
    const uint64_t offset = rhi::kTextureCopyOffsetAlignment;
    const uint32_t pitch = rhi::kTextureCopyRowAlignment;
    rhi::BufferHandle buffer = device().createBuffer(
        {.size = offset + pitch * 4, .memory = rhi::MemoryType::Readback, .debugName = "aligned copy"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->writeTexture(*texture, {}, texels.data());
    list->copyTextureToBuffer(*buffer, offset, pitch, *texture, {});
    list->end();
    submitAndWait(*list);
    const auto* bytes = static_cast<const uint8_t*>(buffer->map());
    for (uint32_t row = 0; row < 4; ++row) {
        const auto* values = reinterpret_cast<const uint32_t*>(bytes + offset + row * pitch);
        for (uint32_t x = 0; x < 8; ++x) {
            EXPECT_EQ(values[x], texels[row * 8 + x]) << "row " << row << " texel " << x;
        }
    }
}

TEST_P(ValidationTest, BufferRangesAndTextureCopiesFollowOneRuleOnEveryBackend) {
    rhi::BufferHandle small = device().createBuffer({.size = 64, .debugName = "small"});
    rhi::BufferHandle large = device().createBuffer({.size = 256, .debugName = "large"});
    rhi::TextureHandle rgba = device().createTexture(smallTexture("rgba8"));
    // Same texel size, another format: Vulkan would copy the bits, D3D12 refuses.
    rhi::TextureHandle uint32 = device().createTexture(smallTexture("r32 uint", rhi::Format::R32_UINT));
    rhi::TextureHandle wide = device().createTexture(
        {.width = 16, .height = 4, .usage = rhi::TextureUsage::Sampled, .debugName = "wide"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    expectRefused([&] { list->copyBuffer(*small, 0, *large, 0, 128); }, {"copyBuffer", "0+128", "small"});
    expectRefused([&] { list->copyBuffer(*large, 0, *small, 32, 64); }, {"copyBuffer", "32+64", "small"});
    const uint32_t words[4] = {};
    expectRefused([&] { list->writeBuffer(*small, words, sizeof(words), 56); },
                  {"writeBuffer", "56+16", "small"});
    expectRefused([&] { list->copyTexture(*uint32, {}, *rgba, {}); }, {"copyTexture", "formats differ"});
    expectRefused([&] { list->copyTexture(*wide, {}, *rgba, {}); }, {"copyTexture", "extents differ"});
    expectRefused([&] { list->copyTexture(*rgba, {.arrayLayer = 1}, *rgba, {}); },
                  {"layer 1", "does not exist"});
    list->end();
}

TEST_P(ValidationTest, BindingsFollowOneRuleOnEveryBackend) {
    LUMINA_REQUIRE_KERNELS();
    const ComputeKernel step = loadComputeKernel(
        "rhi_tests/chain_step", {{rhi::BindingType::BufferSRV, 0}, {rhi::BindingType::BufferUAV, 0}},
        sizeof(gpu::ChainConstants));
    using U = rhi::BufferUsage;
    rhi::BufferHandle output = device().createBuffer(
        {.size = 256, .structStride = 4, .usage = U::Structured | U::Storage, .debugName = "chain output"});
    // Structured usage is what a StructuredBuffer needs; Vulkan alone would take a Raw buffer.
    rhi::BufferHandle rawOnly =
        device().createBuffer({.size = 256, .usage = U::Raw, .debugName = "raw only"});
    // An offset of 16 suits any device's storage alignment, but not the 12-byte elements.
    rhi::BufferHandle triples = device().createBuffer(
        {.size = 240, .structStride = 12, .usage = U::Structured, .debugName = "triples"});
    rhi::BufferHandle readback = device().createBuffer({.size = 256,
                                                        .structStride = 4,
                                                        .usage = U::Structured,
                                                        .memory = rhi::MemoryType::Readback,
                                                        .debugName = "readback input"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    const auto bindInput = [&](rhi::BindingSetItem input) {
        list->setComputeState(
            {.pipeline = step.pipeline,
             .bindings = {
                 {step.layout, {std::move(input), rhi::BindingSetItem::rwStructuredBuffer(0, output)}}}});
        list->pushConstants(gpu::ChainConstants{});
        list->dispatch(1);
    };
    expectRefused([&] { bindInput(rhi::BindingSetItem::structuredBuffer(0, rawOnly)); },
                  {"raw only", "BufferUsage::Structured"});
    expectRefused([&] { bindInput(rhi::BindingSetItem::structuredBuffer(0, triples, {.offset = 16})); },
                  {"triples", "offset 16", "multiple of 12"});
    expectRefused([&] { bindInput(rhi::BindingSetItem::structuredBuffer(0, readback)); },
                  {"readback input", "Readback"});
    expectRefused([&] { bindInput(rhi::BindingSetItem::structuredBuffer(0, output, {.offset = 256})); },
                  {"chain output", "outside its 256 bytes"});
    list->end();
}

LUMINA_INSTANTIATE_GPU_TEST(ValidationTest);

} // namespace
} // namespace lumina::test
