#include "gi/image/image.h"

#include <gtest/gtest.h>

namespace lumina::image {
namespace {

TEST(Image, StartsZeroedWithNamedChannels) {
    Image image(3, 2, {"R", "G", "B", "variance"});
    EXPECT_EQ(image.width(), 3u);
    EXPECT_EQ(image.height(), 2u);
    EXPECT_EQ(image.pixelCount(), 6u);
    EXPECT_EQ(image.channelNames(), (std::vector<std::string>{"R", "G", "B", "variance"}));
    EXPECT_TRUE(image.hasRgb());
    for (float v : image.channel("variance")) {
        EXPECT_EQ(v, 0.0f);
    }
}

TEST(Image, PlanarRowMajorLayout) {
    Image image = Image::rgb(4, 3);
    image.set("G", 2, 1, 7.0f);
    EXPECT_EQ(image.channel("G")[1 * 4 + 2], 7.0f);
    image.setRgb(3, 2, {1.0f, 2.0f, 3.0f});
    const Rgb rgb = image.rgbAt(3, 2);
    EXPECT_EQ(rgb.r, 1.0f);
    EXPECT_EQ(rgb.g, 2.0f);
    EXPECT_EQ(rgb.b, 3.0f);
    EXPECT_EQ(image.channel("B")[2 * 4 + 3], 3.0f);
}

TEST(Image, RgbaFillsAlphaWithOne) {
    const Image image = Image::rgba(2, 2);
    EXPECT_EQ(image.channelNames().back(), "A");
    EXPECT_EQ(image.at("A", 1, 1), 1.0f);
}

TEST(Image, AddAndRemoveChannels) {
    Image image = Image::rgb(2, 2);
    auto albedo = image.addChannel("albedo.R", 0.5f);
    EXPECT_EQ(albedo.size(), 4u);
    EXPECT_EQ(image.at("albedo.R", 1, 0), 0.5f);
    EXPECT_THROW(image.addChannel("albedo.R"), ImageError);
    EXPECT_THROW(image.addChannel(""), ImageError);
    EXPECT_TRUE(image.removeChannel("albedo.R"));
    EXPECT_FALSE(image.removeChannel("albedo.R"));
    EXPECT_FALSE(image.hasChannel("albedo.R"));
}

TEST(Image, ErrorsNameTheProblem) {
    Image image = Image::rgb(2, 2);
    try {
        (void)image.channel("depth");
        FAIL() << "no throw";
    } catch (const ImageError& error) {
        EXPECT_NE(std::string(error.what()).find("depth"), std::string::npos) << error.what();
    }
    EXPECT_THROW((void)image.at("R", 2, 0), ImageError);
    EXPECT_THROW((void)image.at("R", 0, 2), ImageError);
    EXPECT_THROW(Image(0, 4), ImageError);
    EXPECT_THROW(Image(70000, 1), ImageError);
    EXPECT_THROW(Image(2, 2, {"R", "R"}), ImageError);
    Image empty;
    EXPECT_TRUE(empty.empty());
    EXPECT_THROW(empty.addChannel("R"), ImageError);
}

TEST(Image, RequireSameSize) {
    const Image a = Image::rgb(2, 2);
    const Image b = Image::rgb(2, 3);
    EXPECT_NO_THROW(requireSameSize(a, a, "a vs a"));
    try {
        requireSameSize(a, b, "a.exr vs b.exr");
        FAIL() << "no throw";
    } catch (const ImageError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("a.exr vs b.exr"), std::string::npos) << message;
        EXPECT_NE(message.find("2x2 vs 2x3"), std::string::npos) << message;
    }
}

} // namespace
} // namespace lumina::image
