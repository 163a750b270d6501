// Samplers, and sampled 2D, 2D-array and cube textures read by a kernel.
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cstring>

namespace lumina::test {
namespace {

using gpu::SampleConstants;
using gpu::SampleResult;

class SamplingTest : public GpuTest {
protected:
    // Samples a 2D texture, an array and a cube with a point sampler, `dispatches` times in one
    // command list, each with its own binding set, and checks the last dispatch's results.
    void sampleAndCheck(uint32_t dispatches);
};

TEST_P(SamplingTest, SamplersAreCreatedForEveryMode) {
    for (const rhi::Filter filter : {rhi::Filter::Point, rhi::Filter::Linear}) {
        for (const rhi::AddressMode mode : {rhi::AddressMode::Wrap, rhi::AddressMode::Clamp,
                                            rhi::AddressMode::Mirror, rhi::AddressMode::Border}) {
            const rhi::SamplerDesc desc{.minFilter = filter,
                                        .magFilter = filter,
                                        .mipFilter = filter,
                                        .addressU = mode,
                                        .addressV = mode,
                                        .addressW = mode,
                                        .debugName = "sampler"};
            rhi::SamplerHandle sampler = device().createSampler(desc);
            ASSERT_TRUE(sampler);
            EXPECT_EQ(sampler->desc().addressU, mode);
            EXPECT_EQ(sampler->desc().minFilter, filter);
        }
    }
    rhi::SamplerHandle shadow = device().createSampler(
        {.compareEnable = true, .compareOp = rhi::CompareOp::GreaterEqual, .debugName = "shadow comparison"});
    EXPECT_TRUE(shadow->desc().compareEnable);
    rhi::SamplerHandle anisotropic =
        device().createSampler({.maxAnisotropy = 16.0f, .debugName = "anisotropic"});
    EXPECT_EQ(anisotropic->desc().maxAnisotropy, 16.0f);
}

void SamplingTest::sampleAndCheck(uint32_t dispatches) {
    constexpr uint32_t kWidth = 5, kHeight = 3, kLayers = 3, kProbes = kWidth * kHeight;
    auto texel2D = [](uint32_t x, uint32_t y) {
        return std::array<float, 4>{float(x), float(y), 0.5f, 1.0f};
    };
    auto layerValue = [](uint32_t layer) { return std::array<float, 4>{10.0f + layer, 0, 0, 1}; };
    auto faceValue = [](uint32_t face) { return std::array<float, 4>{100.0f + face, 0, 0, 1}; };

    rhi::TextureHandle texture = device().createTexture(
        {.format = rhi::Format::RGBA32_FLOAT, .width = kWidth, .height = kHeight, .debugName = "sampled 2D"});
    rhi::TextureHandle array = device().createTexture({.dimension = rhi::TextureDimension::Texture2DArray,
                                                       .format = rhi::Format::RGBA32_FLOAT,
                                                       .width = 2,
                                                       .height = 2,
                                                       .arrayLayers = kLayers,
                                                       .debugName = "sampled array"});
    // 1x1 faces: any direction inside a face samples its one texel, so only the face order
    // (+X, -X, +Y, -Y, +Z, -Z) is under test.
    rhi::TextureHandle cube = device().createTexture({.dimension = rhi::TextureDimension::TextureCube,
                                                      .format = rhi::Format::RGBA32_FLOAT,
                                                      .arrayLayers = 6,
                                                      .debugName = "sampled cube"});
    const SampleConstants constants{kWidth, kHeight, kLayers, kProbes};
    rhi::BufferHandle constantBuffer = rhi::createBufferWithData(
        device(), {.usage = rhi::BufferUsage::Constant, .debugName = "sample constants"}, &constants,
        sizeof(constants));
    rhi::BufferHandle results =
        device().createBuffer({.size = kProbes * sizeof(SampleResult),
                               .structStride = sizeof(SampleResult),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "sample results"});
    rhi::SamplerHandle point = device().createSampler({.minFilter = rhi::Filter::Point,
                                                       .magFilter = rhi::Filter::Point,
                                                       .mipFilter = rhi::Filter::Point,
                                                       .debugName = "point"});

    const ComputeKernel kernel =
        loadComputeKernel("rhi_tests/sample_texture", {{rhi::BindingType::ConstantBuffer, 0},
                                                       {rhi::BindingType::TextureSRV, 0},
                                                       {rhi::BindingType::TextureSRV, 1},
                                                       {rhi::BindingType::TextureSRV, 2},
                                                       {rhi::BindingType::Sampler, 0},
                                                       {rhi::BindingType::BufferUAV, 0}});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    std::vector<float> texels;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const auto value = texel2D(x, y);
            texels.insert(texels.end(), value.begin(), value.end());
        }
    }
    list->writeTexture(*texture, {}, texels.data());
    for (uint32_t layer = 0; layer < kLayers; ++layer) {
        const auto value = layerValue(layer);
        std::vector<float> layerTexels;
        for (int i = 0; i < 4; ++i) {
            layerTexels.insert(layerTexels.end(), value.begin(), value.end());
        }
        list->writeTexture(*array, {.arrayLayer = layer}, layerTexels.data());
    }
    for (uint32_t face = 0; face < 6; ++face) {
        list->writeTexture(*cube, {.arrayLayer = face}, faceValue(face).data());
    }
    for (uint32_t d = 0; d < dispatches; ++d) {
        list->setComputeState({.pipeline = kernel.pipeline,
                               .bindings = {{kernel.layout,
                                             {rhi::BindingSetItem::constantBuffer(0, constantBuffer),
                                              rhi::BindingSetItem::sampledTexture(0, texture),
                                              rhi::BindingSetItem::sampledTexture(1, array),
                                              rhi::BindingSetItem::sampledTexture(2, cube),
                                              rhi::BindingSetItem::samplerState(0, point),
                                              rhi::BindingSetItem::rwStructuredBuffer(0, results)}}}});
        list->dispatch(1);
    }
    list->end();
    submitAndWait(*list);

    const std::vector<SampleResult> actual = readBack<SampleResult>(*results);
    for (uint32_t probe = 0; probe < kProbes; ++probe) {
        SCOPED_TRACE("probe " + std::to_string(probe));
        const auto expected2D = texel2D(probe % kWidth, probe / kWidth);
        const auto expectedLayer = layerValue(probe % kLayers);
        const auto expectedFace = faceValue(probe % 6);
        for (int c = 0; c < 4; ++c) {
            EXPECT_EQ(actual[probe].sampled2D[c], expected2D[c]);
            EXPECT_EQ(actual[probe].loaded2D[c], expected2D[c]);
            EXPECT_EQ(actual[probe].arrayLayer[c], expectedLayer[c]);
            EXPECT_EQ(actual[probe].cubeFace[c], expectedFace[c]);
        }
    }
}

TEST_P(SamplingTest, KernelSamplesTexturesArraysAndCubeFaces) {
    LUMINA_REQUIRE_KERNELS();
    sampleAndCheck(1);
}

// More sampler bindings in one list than a D3D12 shader-visible sampler heap holds (2048): the
// backend must share identical sampler tables (a frame of `city` binds thousands).
TEST_P(SamplingTest, ThousandsOfSamplerBindingsInOneList) {
    LUMINA_REQUIRE_KERNELS();
    sampleAndCheck(3000);
}

LUMINA_INSTANTIATE_GPU_TEST(SamplingTest);

} // namespace
} // namespace lumina::test
