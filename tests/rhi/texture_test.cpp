// Texture copies and clears.
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/rhi/texel_patterns.h"

#include <cstring>

namespace lumina::test {
namespace {

using TextureTest = GpuTest;

template <typename T>
std::vector<T> asValues(const std::vector<uint8_t>& bytes) {
    std::vector<T> values(bytes.size() / sizeof(T));
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
    return values;
}

TEST_P(TextureTest, CopyTextureBetweenLayersAndTextures) {
    const rhi::TextureDesc desc{.dimension = rhi::TextureDimension::Texture2DArray,
                                .format = rhi::Format::RGBA16_FLOAT,
                                .width = 6,
                                .height = 3,
                                .arrayLayers = 3,
                                .debugName = "copy source"};
    rhi::TextureHandle source = device().createTexture(desc);
    rhi::TextureDesc targetDesc = desc;
    targetDesc.debugName = "copy target";
    rhi::TextureHandle target = device().createTexture(targetDesc);
    const std::vector<uint8_t> pattern = texelPattern(desc.format, 6 * 3, 42);
    const std::vector<uint8_t> zeros(pattern.size(), 0);

    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->writeTexture(*source, {.arrayLayer = 1}, pattern.data());
    for (uint32_t layer = 0; layer < 3; ++layer) {
        list->writeTexture(*target, {.arrayLayer = layer}, zeros.data());
    }
    list->copyTexture(*target, {.arrayLayer = 2}, *source, {.arrayLayer = 1});
    list->end();
    submitAndWait(*list);

    EXPECT_EQ(rhi::readTexture(device(), *target, {.arrayLayer = 2}), pattern);
    EXPECT_EQ(rhi::readTexture(device(), *target, {.arrayLayer = 0}), zeros);
    EXPECT_EQ(rhi::readTexture(device(), *target, {.arrayLayer = 1}), zeros);
}

TEST_P(TextureTest, ClearColorFillsEveryMipAndLayer) {
    rhi::TextureHandle unorm = device().createTexture({.dimension = rhi::TextureDimension::Texture2DArray,
                                                       .format = rhi::Format::RGBA8_UNORM,
                                                       .width = 5,
                                                       .height = 4,
                                                       .arrayLayers = 2,
                                                       .mipLevels = 2,
                                                       .debugName = "clear rgba8"});
    rhi::TextureHandle floats = device().createTexture(
        {.format = rhi::Format::RGBA32_FLOAT, .width = 3, .height = 3, .debugName = "clear rgba32f"});
    rhi::TextureHandle uints = device().createTexture(
        {.format = rhi::Format::R32_UINT, .width = 7, .height = 2, .debugName = "clear r32ui"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->clearColor(*unorm, {1.0f, 0.0f, 1.0f, 0.0f});
    list->clearColor(*floats, {0.5f, -2.0f, 1e6f, 3.25f});
    list->clearColorUint(*uints, {0xCAFEF00D, 0, 0, 0});
    list->end();
    submitAndWait(*list);

    for (uint32_t layer = 0; layer < 2; ++layer) {
        for (uint32_t mip = 0; mip < 2; ++mip) {
            const std::vector<uint8_t> texels = rhi::readTexture(device(), *unorm, {mip, layer});
            for (size_t i = 0; i < texels.size(); i += 4) {
                ASSERT_EQ(texels[i + 0], 255);
                ASSERT_EQ(texels[i + 1], 0);
                ASSERT_EQ(texels[i + 2], 255);
                ASSERT_EQ(texels[i + 3], 0);
            }
        }
    }
    const std::vector<float> floatTexels = asValues<float>(rhi::readTexture(device(), *floats));
    for (size_t i = 0; i < floatTexels.size(); i += 4) {
        ASSERT_EQ(floatTexels[i + 0], 0.5f);
        ASSERT_EQ(floatTexels[i + 1], -2.0f);
        ASSERT_EQ(floatTexels[i + 2], 1e6f);
        ASSERT_EQ(floatTexels[i + 3], 3.25f);
    }
    EXPECT_EQ(asValues<uint32_t>(rhi::readTexture(device(), *uints)), std::vector<uint32_t>(14, 0xCAFEF00D));
}

TEST_P(TextureTest, ClearColorWorksForEveryUsage) {
    // Backends may clear through different paths per usage (D3D12: a render-target view, a
    // UAV, or a copy from upload memory); each must write every mip and layer.
    const rhi::TextureUsage usages[] = {rhi::TextureUsage::Sampled,
                                        rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                        rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage};
    for (const rhi::TextureUsage usage : usages) {
        SCOPED_TRACE("usage " + std::to_string(uint32_t(usage)));
        rhi::TextureHandle floats =
            device().createTexture({.dimension = rhi::TextureDimension::Texture2DArray,
                                    .format = rhi::Format::RGBA16_FLOAT,
                                    .width = 6,
                                    .height = 5,
                                    .arrayLayers = 2,
                                    .mipLevels = 3,
                                    .usage = usage,
                                    .debugName = "cleared half floats"});
        rhi::TextureHandle uints = device().createTexture({.format = rhi::Format::RG32_UINT,
                                                           .width = 4,
                                                           .height = 4,
                                                           .mipLevels = 2,
                                                           .usage = usage,
                                                           .debugName = "cleared uints"});
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        list->clearColor(*floats, {0.25f, -1.5f, 2.0f, 1.0f});
        list->clearColorUint(*uints, {7, 123456, 0, 0});
        list->end();
        submitAndWait(*list);
        // 0.25, -1.5, 2.0, 1.0 as IEEE half floats.
        const std::vector<uint16_t> half = {0x3400, 0xBE00, 0x4000, 0x3C00};
        for (uint32_t layer = 0; layer < 2; ++layer) {
            for (uint32_t mip = 0; mip < 3; ++mip) {
                const std::vector<uint16_t> texels =
                    asValues<uint16_t>(rhi::readTexture(device(), *floats, {mip, layer}));
                for (size_t i = 0; i < texels.size(); ++i) {
                    ASSERT_EQ(texels[i], half[i % 4]) << "mip " << mip << " layer " << layer << " at " << i;
                }
            }
        }
        for (uint32_t mip = 0; mip < 2; ++mip) {
            const std::vector<uint32_t> texels =
                asValues<uint32_t>(rhi::readTexture(device(), *uints, {mip, 0}));
            for (size_t i = 0; i < texels.size(); i += 2) {
                ASSERT_EQ(texels[i], 7u) << "mip " << mip;
                ASSERT_EQ(texels[i + 1], 123456u) << "mip " << mip;
            }
        }
    }
}

TEST_P(TextureTest, ClearDepth) {
    rhi::TextureHandle depth = device().createTexture({.format = rhi::Format::D32_FLOAT,
                                                       .width = 8,
                                                       .height = 8,
                                                       .usage = rhi::TextureUsage::DepthStencil,
                                                       .debugName = "clear depth"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->clearDepth(*depth, 0.375f);
    list->end();
    submitAndWait(*list);
    EXPECT_EQ(asValues<float>(rhi::readTexture(device(), *depth)), std::vector<float>(64, 0.375f));
}

TEST_P(TextureTest, InvalidDescriptionsThrowWithTheTextureName) {
    try {
        device().createTexture({.dimension = rhi::TextureDimension::TextureCube,
                                .width = 4,
                                .height = 8,
                                .arrayLayers = 6,
                                .debugName = "lopsided cube"});
        ADD_FAILURE() << "a non-square cube was accepted";
    } catch (const rhi::Error& error) {
        EXPECT_NE(std::string(error.what()).find("lopsided cube"), std::string::npos) << error.what();
    }
    EXPECT_THROW(device().createTexture({.format = rhi::Format::Unknown, .debugName = "no format"}),
                 rhi::Error);
    EXPECT_THROW(
        device().createTexture({.width = 4, .height = 4, .mipLevels = 4, .debugName = "too many mips"}),
        rhi::Error);
}

LUMINA_INSTANTIATE_GPU_TEST(TextureTest);

} // namespace
} // namespace lumina::test
