#include "gi/image/colormap.h"
#include "gi/image/png.h"
#include "tests/image/temp_dir.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb_image.h>

namespace lumina::image {
namespace {

class Png : public testing::TempDir {};

struct Decoded {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;
    std::array<uint8_t, 3> at(int x, int y) const {
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

Decoded decode(const std::filesystem::path& path) {
    Decoded out;
    int components = 0;
    unsigned char* data = stbi_load(path.string().c_str(), &out.width, &out.height, &components, 3);
    if (!data) {
        ADD_FAILURE() << path << ": stb_image cannot decode: " << stbi_failure_reason();
        return out;
    }
    EXPECT_EQ(components, 3) << "written as RGB without alpha";
    out.rgb.assign(data, data + size_t(out.width) * size_t(out.height) * 3);
    stbi_image_free(data);
    return out;
}

uint8_t expected8(float linear) {
    return uint8_t(std::lround(srgbEncode(linear) * 255.0f));
}

TEST_F(Png, DisplayValuesQuantiseByRounding) {
    Image display = Image::rgb(3, 1);
    display.setRgb(0, 0, {0.0f, 0.5f, 1.0f});
    display.setRgb(1, 0, {-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN()});
    display.setRgb(2, 0, {0.2f, 0.4f, 0.6f});
    writeDisplayPng(path("d.png"), display);
    const Decoded png = decode(path("d.png"));
    ASSERT_EQ(png.width, 3);
    ASSERT_EQ(png.height, 1);
    EXPECT_EQ(png.at(0, 0), (std::array<uint8_t, 3>{0, 128, 255}));
    EXPECT_EQ(png.at(1, 0), (std::array<uint8_t, 3>{0, 255, 0}));
    EXPECT_EQ(png.at(2, 0), (std::array<uint8_t, 3>{51, 102, 153}));
}

TEST_F(Png, LinearImageIsEncodedAsSrgb) {
    Image linear = Image::rgb(2, 2);
    linear.setRgb(0, 0, {0.0f, 0.18f, 1.0f});
    linear.setRgb(1, 0, {0.5f, 0.0031308f, 0.214f});
    linear.setRgb(0, 1, {0.25f, 0.25f, 0.25f});
    writePng(path("clamp.png"), linear, {.tonemap = Tonemap::Clamp});
    const Decoded png = decode(path("clamp.png"));
    ASSERT_EQ(png.width, 2);
    ASSERT_EQ(png.height, 2);
    // sRGB of known values: 0.18 -> 0.4614 -> 118, 0.5 -> 0.7354 -> 188, 0.214 -> 0.49995 -> 127.
    EXPECT_EQ(png.at(0, 0), (std::array<uint8_t, 3>{0, 118, 255}));
    EXPECT_EQ(png.at(1, 0), (std::array<uint8_t, 3>{188, 10, 127}));
    EXPECT_EQ(png.at(0, 1)[0], expected8(0.25f));
    EXPECT_EQ(png.at(1, 1), (std::array<uint8_t, 3>{0, 0, 0}));
}

TEST_F(Png, TonemappedImageUsesTheAcesCurveAndExposure) {
    Image linear = Image::rgb(1, 1);
    linear.setRgb(0, 0, {0.5f, 1.0f, 1000.0f});
    writePng(path("aces.png"), linear, {.exposureEv = 1.0f});
    const Decoded png = decode(path("aces.png"));
    ASSERT_EQ(png.width, 1);
    const float aces1 = 2.54f / 3.16f; // the curve at exposed radiance 1 (0.5 * 2^1)
    EXPECT_EQ(png.at(0, 0)[0], expected8(aces1));
    EXPECT_EQ(png.at(0, 0)[2], 255);
}

TEST_F(Png, HeatmapUsesMagmaEnds) {
    const std::vector<float> values = {0.0f, 0.5f, 1.0f, 3.0f, std::numeric_limits<float>::quiet_NaN(),
                                       -1.0f};
    writeHeatmapPng(path("heat.png"), values, 3, 2);
    const Decoded png = decode(path("heat.png"));
    ASSERT_EQ(png.width, 3);
    ASSERT_EQ(png.height, 2);
    EXPECT_EQ(png.at(0, 0), magma(0.0f));
    EXPECT_EQ(png.at(1, 0), magma(0.5f));
    EXPECT_EQ(png.at(2, 0), magma(1.0f));
    EXPECT_EQ(png.at(0, 1), magma(1.0f)); // clamped
    EXPECT_EQ(png.at(1, 1), kHeatmapInvalid);
    EXPECT_EQ(png.at(2, 1), magma(0.0f));
    // Dark to bright: luminance rises monotonically along the map.
    float previous = -1.0f;
    for (int i = 0; i <= 64; ++i) {
        const Rgb8 c = magma(float(i) / 64.0f);
        const float luma = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
        EXPECT_GE(luma, previous) << i;
        previous = luma;
    }
    // A maximum scales the values.
    writeHeatmapPng(path("heat2.png"), values, 3, 2, 2.0f);
    EXPECT_EQ(decode(path("heat2.png")).at(2, 0), magma(0.5f));
}

TEST_F(Png, Errors) {
    const Image image = Image::rgb(2, 2);
    try {
        writePng(path("missing/dir/out.png"), image);
        FAIL() << "no throw";
    } catch (const ImageError& error) {
        EXPECT_NE(std::string(error.what()).find("out.png"), std::string::npos) << error.what();
    }
    EXPECT_THROW(writePng(path("a.png"), Image()), ImageError);
    EXPECT_THROW(writePng(path("a.png"), Image(2, 2, {"Y"})), ImageError);
    const std::vector<float> values(4, 0.0f);
    EXPECT_THROW(writeHeatmapPng(path("h.png"), values, 3, 2), ImageError);
    EXPECT_THROW(writeHeatmapPng(path("h.png"), values, 2, 2, 0.0f), ImageError);
}

} // namespace
} // namespace lumina::image
