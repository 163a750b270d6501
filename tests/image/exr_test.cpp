// The EXR contract of gi/image/exr.h, whichever library implements it (OpenEXR or tinyexr:
// tests/image/CMakeLists.txt builds these tests against each one available).
#include "gi/image/exr.h"
#include "tests/image/temp_dir.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::image {
namespace {

class Exr : public testing::TempDir {};

// Values of both signs from 1e-7 to 1e4 (inside half's range), different in every channel.
Image testImage() {
    Image image(5, 3, {"R", "G", "B", "A", "variance", "albedo.R", "albedo.G", "albedo.B"});
    const float scales[] = {1.0e-3f, 1.0f, 1.0e3f};
    int n = 0;
    for (const std::string& name : image.channelNames()) {
        for (float& v : image.channel(name)) {
            const float fraction = float(n * 7919 % 1000) / 1000.0f - 0.5f;
            v = fraction * 20.0f * scales[n % 3];
            ++n;
        }
    }
    image.set("R", 0, 0, 1.0e-7f);
    image.set("G", 1, 0, 12345.678f);
    return image;
}

// Options set field by field: GCC 12 warns (-Wmissing-field-initializers) on designated
// initialisers that leave out the vector member.
ExrWriteOptions options(ExrPixelType type, ExrCompression compression = ExrCompression::Zip) {
    ExrWriteOptions out;
    out.pixelType = type;
    out.compression = compression;
    return out;
}

void expectMessageHas(const std::function<void()>& call, const std::vector<std::string>& parts) {
    try {
        call();
        FAIL() << "expected an ImageError";
    } catch (const ImageError& error) {
        for (const std::string& part : parts) {
            EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
                << "'" << error.what() << "' lacks '" << part << "'";
        }
    }
}

TEST_F(Exr, FloatRoundTripIsExactAndKeepsExtraChannels) {
    const Image original = testImage();
    writeExr(path("f.exr"), original, options(ExrPixelType::Float));
    const Image read = readExr(path("f.exr"));
    ASSERT_EQ(read.width(), 5u);
    ASSERT_EQ(read.height(), 3u);
    // R, G, B, A first, then the rest alphabetically (the file's order).
    EXPECT_EQ(read.channelNames(),
              (std::vector<std::string>{"R", "G", "B", "A", "albedo.B", "albedo.G", "albedo.R", "variance"}));
    for (const std::string& name : original.channelNames()) {
        const auto a = original.channel(name);
        const auto b = read.channel(name);
        for (size_t i = 0; i < a.size(); ++i) {
            EXPECT_EQ(a[i], b[i]) << name << "[" << i << "]";
        }
    }
}

TEST_F(Exr, HalfRoundTripIsWithinHalfPrecision) {
    const Image original = testImage();
    writeExr(path("h.exr"), original, options(ExrPixelType::Half, ExrCompression::Piz));
    const Image read = readExr(path("h.exr"));
    for (const std::string& name : original.channelNames()) {
        const auto a = original.channel(name);
        const auto b = read.channel(name);
        for (size_t i = 0; i < a.size(); ++i) {
            // Half: 11 significant bits, rounding to nearest: relative error <= 2^-11 for normals;
            // absolute 2^-25 covers the subnormal range.
            EXPECT_NEAR(b[i], a[i], std::fabs(a[i]) * std::ldexp(1.0f, -11) + std::ldexp(1.0f, -25)) << name;
        }
    }
}

TEST_F(Exr, PerChannelPixelTypes) {
    const Image original = testImage();
    ExrWriteOptions mixed = options(ExrPixelType::Half);
    mixed.channelTypes = {{"variance", ExrPixelType::Float}};
    writeExr(path("mixed.exr"), original, mixed);
    const ExrInfo info = readExrInfo(path("mixed.exr"));
    EXPECT_EQ(info.width, 5u);
    EXPECT_EQ(info.height, 3u);
    ASSERT_EQ(info.channels.size(), 8u);
    for (const ExrChannelInfo& channel : info.channels) {
        EXPECT_EQ(channel.pixelType, channel.name == "variance" ? "float" : "half") << channel.name;
    }
    const Image read = readExr(path("mixed.exr"));
    EXPECT_EQ(read.at("variance", 4, 2), original.at("variance", 4, 2));
    ExrWriteOptions unknown;
    unknown.channelTypes = {{"depth", ExrPixelType::Half}};
    expectMessageHas([&] { writeExr(path("bad.exr"), original, unknown); }, {"bad.exr", "depth"});
}

TEST_F(Exr, HalfOverflowBecomesInfinity) {
    Image image = Image::rgb(1, 1);
    image.setRgb(0, 0, {70000.0f, 65504.0f, -1.0e6f});
    writeExr(path("big.exr"), image, options(ExrPixelType::Half));
    const Rgb read = readExr(path("big.exr")).rgbAt(0, 0);
    EXPECT_EQ(read.r, std::numeric_limits<float>::infinity());
    EXPECT_EQ(read.g, 65504.0f);
    EXPECT_EQ(read.b, -std::numeric_limits<float>::infinity());
}

TEST_F(Exr, AlphaIsOptional) {
    Image image = Image::rgb(2, 2);
    image.fillRgb({0.25f, 0.5f, 1.0f});
    writeExr(path("rgb.exr"), image);
    const Image read = readExr(path("rgb.exr"));
    EXPECT_EQ(read.channelNames(), (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(read.rgbAt(1, 1).g, 0.5f);
}

TEST_F(Exr, MissingFile) {
    expectMessageHas([&] { readExr(path("nothing.exr")); }, {"nothing.exr", "not found"});
    expectMessageHas([&] { readExrInfo(path("nothing.exr")); }, {"nothing.exr", "not found"});
}

TEST_F(Exr, NotAnExr) {
    std::ofstream(path("text.exr")) << "this is not an image\n";
    expectMessageHas([&] { readExr(path("text.exr")); }, {"text.exr", "not an OpenEXR file"});
    std::ofstream(path("empty.exr")).close();
    expectMessageHas([&] { readExr(path("empty.exr")); }, {"empty.exr"});
    expectMessageHas([&] { readExr(""); }, {"not found"});
}

TEST_F(Exr, DirectoryIsNotAnExr) {
    std::filesystem::create_directories(path("dir.exr"));
    expectMessageHas([&] { readExr(path("dir.exr")); }, {"dir.exr", "directory"});
}

TEST_F(Exr, MissingRgbChannels) {
    Image gray(2, 2, {"Y", "A"});
    writeExr(path("gray.exr"), gray);
    expectMessageHas([&] { readExr(path("gray.exr")); }, {"gray.exr", "missing channel(s) R, G, B", "A, Y"});
    Image noBlue(2, 2, {"R", "G"});
    writeExr(path("rg.exr"), noBlue);
    expectMessageHas([&] { readExr(path("rg.exr")); }, {"rg.exr", "missing channel(s) B"});
}

TEST_F(Exr, TruncatedFileIsAnErrorNotACrash) {
    Image image(64, 64, {"R", "G", "B"});
    image.fillRgb({1.0f, 2.0f, 3.0f});
    writeExr(path("full.exr"), image, options(ExrPixelType::Float, ExrCompression::None));
    const auto size = std::filesystem::file_size(path("full.exr"));
    std::filesystem::copy_file(path("full.exr"), path("cut.exr"));
    std::filesystem::resize_file(path("cut.exr"), size / 2);
    expectMessageHas([&] { readExr(path("cut.exr")); }, {"cut.exr"});
    // Damage inside the pixel data too: garbage bytes after the header.
    std::filesystem::copy_file(path("full.exr"), path("garbled.exr"));
    {
        std::fstream file(path("garbled.exr"), std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(std::streamoff(size / 3));
        const std::string junk(512, '\xff');
        file.write(junk.data(), std::streamsize(junk.size()));
    }
    try {
        (void)readExr(path("garbled.exr")); // uncompressed pixel bytes may read as values: either is fine
    } catch (const ImageError& error) {
        EXPECT_NE(std::string(error.what()).find("garbled.exr"), std::string::npos);
    }
}

TEST_F(Exr, UnwritablePath) {
    const Image image = Image::rgb(2, 2);
    expectMessageHas([&] { writeExr(path("no/such/dir/out.exr"), image); }, {"out.exr", "cannot write"});
    expectMessageHas([&] { writeExr(path("empty.exr"), Image()); }, {"empty.exr", "empty"});
}

} // namespace
} // namespace lumina::image
