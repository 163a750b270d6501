// Upload and readback of every format, for every texture dimension: each layer (or 3D slice)
// and each mip holds its own values, written through writeTexture (mip 0) and through a
// pitched copyBufferToTexture (mip 1), and must read back bit for bit.
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/rhi/texel_patterns.h"

#include <cstring>
#include <tuple>

namespace lumina::test {
namespace {

using Param = std::tuple<rhi::Api, rhi::Format, rhi::TextureDimension>;

} // namespace
} // namespace lumina::test

namespace lumina::rhi {
inline void PrintTo(TextureDimension dimension, std::ostream* out) {
    *out << textureDimensionName(dimension);
}
} // namespace lumina::rhi

namespace lumina::test {
namespace {

class TextureFormatTest : public GpuTestFixture, public ::testing::WithParamInterface<Param> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

// Odd sizes catch row-pitch mistakes; two mips each.
rhi::TextureDesc descFor(rhi::Format format, rhi::TextureDimension dimension) {
    rhi::TextureDesc desc;
    desc.dimension = dimension;
    desc.format = format;
    desc.mipLevels = 2;
    desc.usage = rhi::TextureUsage::Sampled;
    switch (dimension) {
    case rhi::TextureDimension::Texture2D:
        desc.width = 13, desc.height = 7;
        break;
    case rhi::TextureDimension::Texture2DArray:
        desc.width = 9, desc.height = 5, desc.arrayLayers = 4;
        break;
    case rhi::TextureDimension::Texture3D:
        desc.width = 7, desc.height = 5, desc.depth = 4;
        break;
    case rhi::TextureDimension::TextureCube:
        desc.width = desc.height = 4, desc.arrayLayers = 6;
        break;
    case rhi::TextureDimension::TextureCubeArray:
        desc.width = desc.height = 4, desc.arrayLayers = 12;
        break;
    }
    desc.debugName = std::string(rhi::formatInfo(format).name) + " " + rhi::textureDimensionName(dimension);
    return desc;
}

TEST_P(TextureFormatTest, UploadAndReadBackEveryLayerAndMip) {
    const auto [api, format, dimension] = GetParam();
    if (rhi::isDepthFormat(format) && dimension == rhi::TextureDimension::Texture3D) {
        GTEST_SKIP() << "neither API has 3D depth textures";
    }
    const rhi::TextureDesc desc = descFor(format, dimension);
    rhi::TextureHandle texture = device().createTexture(desc);
    const uint32_t texelBytes = rhi::formatInfo(format).bytesPerTexel;
    const uint32_t mip1Width = rhi::mipExtent(desc.width, 1);
    const uint32_t mip1Height = rhi::mipExtent(desc.height, 1);
    const uint32_t mip1Depth =
        dimension == rhi::TextureDimension::Texture3D ? rhi::mipExtent(desc.depth, 1) : 1;
    const uint32_t pitch = rhi::alignedRowPitch(mip1Width, format);
    const uint64_t layerBytes =
        (uint64_t(pitch) * mip1Height * mip1Depth + rhi::kTextureCopyOffsetAlignment - 1) /
        rhi::kTextureCopyOffsetAlignment * rhi::kTextureCopyOffsetAlignment;
    rhi::BufferHandle staging = device().createBuffer({.size = layerBytes * desc.arrayLayers,
                                                       .memory = rhi::MemoryType::Upload,
                                                       .debugName = "mip 1 staging"});

    // expected[layer][mip]
    std::vector<std::array<std::vector<uint8_t>, 2>> expected(desc.arrayLayers);
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    for (uint32_t layer = 0; layer < desc.arrayLayers; ++layer) {
        const size_t mip0Texels = size_t(desc.width) * desc.height * desc.depth;
        expected[layer][0] = texelPattern(format, mip0Texels, layer * 2);
        list->writeTexture(*texture, {.mipLevel = 0, .arrayLayer = layer}, expected[layer][0].data());

        const size_t mip1Texels = size_t(mip1Width) * mip1Height * mip1Depth;
        expected[layer][1] = texelPattern(format, mip1Texels, layer * 2 + 1);
        auto* rows = static_cast<uint8_t*>(staging->map()) + layer * layerBytes;
        for (uint32_t row = 0; row < mip1Height * mip1Depth; ++row) {
            std::memcpy(rows + size_t(row) * pitch,
                        expected[layer][1].data() + size_t(row) * mip1Width * texelBytes,
                        size_t(mip1Width) * texelBytes);
        }
        list->copyBufferToTexture(*texture, {.mipLevel = 1, .arrayLayer = layer}, *staging,
                                  layer * layerBytes, pitch);
    }
    list->end();
    submitAndWait(*list);

    for (uint32_t layer = 0; layer < desc.arrayLayers; ++layer) {
        for (uint32_t mip = 0; mip < 2; ++mip) {
            const std::vector<uint8_t> actual = rhi::readTexture(device(), *texture, {mip, layer});
            ASSERT_EQ(actual.size(), expected[layer][mip].size());
            for (size_t byte = 0; byte < actual.size(); ++byte) {
                ASSERT_EQ(actual[byte], expected[layer][mip][byte])
                    << "layer " << layer << " mip " << mip << " texel " << byte / texelBytes << " byte "
                    << byte % texelBytes;
            }
        }
    }
}

std::vector<rhi::Format> allFormats() {
    std::vector<rhi::Format> formats;
    for (uint32_t f = 1; f < static_cast<uint32_t>(rhi::Format::Count); ++f) {
        formats.push_back(static_cast<rhi::Format>(f));
    }
    return formats;
}

std::string paramName(const ::testing::TestParamInfo<Param>& info) {
    const auto [api, format, dimension] = info.param;
    return std::string(rhi::apiName(api)) + "_" + std::string(rhi::formatInfo(format).name) + "_" +
           rhi::textureDimensionName(dimension);
}

INSTANTIATE_TEST_SUITE_P(Backends, TextureFormatTest,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::ValuesIn(allFormats()),
                                            ::testing::Values(rhi::TextureDimension::Texture2D,
                                                              rhi::TextureDimension::Texture2DArray,
                                                              rhi::TextureDimension::Texture3D,
                                                              rhi::TextureDimension::TextureCube,
                                                              rhi::TextureDimension::TextureCubeArray)),
                         paramName);

} // namespace
} // namespace lumina::test
