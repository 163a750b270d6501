// gi/image/exr.h against files OpenEXR itself writes and reads, whichever library implements
// exr.h: a data window inside the display window, and every channel of what writeExr wrote
// read back by OpenEXR (so tinyexr's files are real OpenEXR files). Built where OpenEXR is.
#include "gi/image/exr.h"
#include "tests/image/temp_dir.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <gtest/gtest.h>

namespace lumina::image {
namespace {

class ExrOpenExr : public testing::TempDir {};

// A file whose data window is smaller than, and offset inside, its display window.
TEST_F(ExrOpenExr, DataWindowIsPlacedInTheDisplayWindow) {
    const Imath::Box2i display({0, 0}, {3, 2});
    const Imath::Box2i data({1, 1}, {2, 2});
    Imf::Header header(display, data);
    for (const char* name : {"R", "G", "B"}) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    std::vector<float> plane = {1.0f, 2.0f, 3.0f, 4.0f}; // 2x2, data-window order
    Imf::FrameBuffer frameBuffer;
    for (const char* name : {"R", "G", "B"}) {
        frameBuffer.insert(
            name, Imf::Slice::Make(Imf::FLOAT, plane.data(), data, sizeof(float), 2 * sizeof(float)));
    }
    {
        Imf::OutputFile file(path("window.exr").string().c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(2);
    }
    const Image read = readExr(path("window.exr"));
    ASSERT_EQ(read.width(), 4u);
    ASSERT_EQ(read.height(), 3u);
    EXPECT_EQ(read.at("R", 0, 0), 0.0f);
    EXPECT_EQ(read.at("R", 1, 1), 1.0f);
    EXPECT_EQ(read.at("R", 2, 1), 2.0f);
    EXPECT_EQ(read.at("G", 1, 2), 3.0f);
    EXPECT_EQ(read.at("B", 2, 2), 4.0f);
    EXPECT_EQ(read.at("B", 3, 2), 0.0f);
}

TEST_F(ExrOpenExr, WhatWriteExrWritesOpenExrReads) {
    Image original(3, 2, {"R", "G", "B", "A", "variance"});
    int n = 0;
    for (const std::string& name : original.channelNames()) {
        for (float& v : original.channel(name)) {
            v = float(n++) * 0.375f - 2.0f;
        }
    }
    for (ExrCompression compression : {ExrCompression::None, ExrCompression::Zip, ExrCompression::Piz}) {
        ExrWriteOptions options;
        options.compression = compression;
        options.channelTypes = {{"variance", ExrPixelType::Half}}; // exact in half: multiples of 1/8
        writeExr(path("out.exr"), original, options);

        Imf::InputFile file(path("out.exr").string().c_str());
        const Imath::Box2i window = file.header().dataWindow();
        ASSERT_EQ(window.max.x - window.min.x + 1, 3);
        ASSERT_EQ(window.max.y - window.min.y + 1, 2);
        EXPECT_EQ(file.header().channels().findChannel("variance")->type, Imf::HALF);
        EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::FLOAT);
        Imf::FrameBuffer frameBuffer;
        std::vector<std::vector<float>> planes;
        const std::vector<std::string> names = original.channelNames();
        planes.reserve(names.size());
        for (const std::string& name : names) {
            std::vector<float>& plane = planes.emplace_back(original.pixelCount(), -99.0f);
            frameBuffer.insert(name, Imf::Slice::Make(Imf::FLOAT, plane.data(), window, sizeof(float),
                                                      sizeof(float) * original.width()));
        }
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
        for (size_t c = 0; c < names.size(); ++c) {
            const auto expected = original.channel(names[c]);
            for (size_t i = 0; i < expected.size(); ++i) {
                EXPECT_EQ(planes[c][i], expected[i])
                    << names[c] << "[" << i << "], compression " << int(compression);
            }
        }
    }
}

} // namespace
} // namespace lumina::image
