// gi/image/exr.h with OpenEXR (Linux, and Windows through vcpkg). exr_tinyexr.cpp is the other
// implementation, for builds without OpenEXR (the MinGW-w64 cross build).
#include "gi/image/exr.h"

#include "gi/image/exr_checks.h"

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfTestFile.h>
#include <ImfVersion.h>
#include <ImfXdr.h>
#include <algorithm>
#include <exception>
#include <half.h>

namespace lumina::image {

namespace {

using exr_checks::fail;
using exr_checks::Window;

std::string fileName(const std::filesystem::path& path) {
    return path.string();
}

const char* pixelTypeName(Imf::PixelType type) {
    switch (type) {
    case Imf::HALF:
        return "half";
    case Imf::FLOAT:
        return "float";
    case Imf::UINT:
        return "uint";
    default:
        return "unknown";
    }
}

// Missing, unreadable, not an EXR or deep: fails with a message naming the file.
void checkReadable(const std::filesystem::path& path) {
    exr_checks::checkFileExists(path);
    bool tiled = false;
    bool deep = false;
    bool multiPart = false;
    if (!Imf::isOpenExrFile(fileName(path).c_str(), tiled, deep, multiPart)) {
        fail(path, "not an OpenEXR file (or unreadable)");
    }
    if (deep) {
        fail(path, "deep OpenEXR images are not supported");
    }
}

Window toWindow(const Imath::Box2i& box) {
    return {box.min.x, box.min.y, box.max.x, box.max.y};
}

// OpenEXR's InputFile allocates its line buffers and decompressor for the data window its
// header declares before reading a pixel: a 976-byte file declaring a huge window made it
// allocate 2 GiB (found by the OpenEXR fuzzer, tests/fuzz/regressions/exr_openexr/). The header
// is read alone first and its windows checked against the image limits.
void checkHeaderWindows(const std::filesystem::path& path) {
    Imf::StdIFStream stream(fileName(path).c_str());
    int magic = 0;
    int version = 0;
    Imf::Xdr::read<Imf::StreamIO>(stream, magic);
    Imf::Xdr::read<Imf::StreamIO>(stream, version);
    if (magic != Imf::MAGIC) {
        fail(path, "not an OpenEXR file (or unreadable)");
    }
    Imf::Header header;
    header.readFrom(stream, version);
    exr_checks::checkWindow(path, toWindow(header.displayWindow()), "display");
    exr_checks::checkWindow(path, toWindow(header.dataWindow()), "data");
}

ExrInfo infoFromHeader(const Imf::Header& header) {
    const Window display = toWindow(header.displayWindow());
    ExrInfo info;
    info.width = uint32_t(std::max<int64_t>(display.width(), 0));
    info.height = uint32_t(std::max<int64_t>(display.height(), 0));
    info.tiled = header.hasTileDescription();
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        info.channels.push_back({it.name(), pixelTypeName(it.channel().type)});
    }
    return info;
}

Image readPixels(const std::filesystem::path& path) {
    checkHeaderWindows(path);
    Imf::InputFile file(fileName(path).c_str());
    const Imf::Header& header = file.header();
    const Window display = toWindow(header.displayWindow());
    const Window data = toWindow(header.dataWindow());
    exr_checks::checkWindow(path, display, "display");
    exr_checks::checkWindow(path, data, "data");

    const Imf::ChannelList& channels = header.channels();
    std::vector<std::string> fileChannels;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        fileChannels.emplace_back(it.name());
    }
    exr_checks::checkHasRgb(path, fileChannels);
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
            fail(path, "channel '" + std::string(it.name()) + "' is subsampled, which is not supported");
        }
    }

    // Read the data window into planes of its own size, then place it in the display window.
    const std::vector<std::string> order = exr_checks::readOrder(fileChannels);
    const size_t dataPixels = size_t(data.width()) * size_t(data.height());
    std::vector<std::vector<float>> planes(order.size(), std::vector<float>(dataPixels, 0.0f));
    Imf::FrameBuffer frameBuffer;
    for (size_t c = 0; c < order.size(); ++c) {
        frameBuffer.insert(order[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), header.dataWindow(),
                                                      sizeof(float), sizeof(float) * size_t(data.width())));
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(data.minY, data.maxY);

    return exr_checks::placeInDisplayWindow(display, data, order, planes);
}

Imf::Compression toImf(ExrCompression compression) {
    switch (compression) {
    case ExrCompression::None:
        return Imf::NO_COMPRESSION;
    case ExrCompression::Piz:
        return Imf::PIZ_COMPRESSION;
    case ExrCompression::Zip:
        break;
    }
    return Imf::ZIP_COMPRESSION;
}

} // namespace

ExrInfo readExrInfo(const std::filesystem::path& path) {
    checkReadable(path);
    try {
        checkHeaderWindows(path);
        Imf::InputFile file(fileName(path).c_str());
        return infoFromHeader(file.header());
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& error) {
        fail(path, std::string("cannot read EXR header: ") + error.what());
    }
}

Image readExr(const std::filesystem::path& path) {
    checkReadable(path);
    return exr_checks::readReportingErrors(path, [&] { return readPixels(path); });
}

void writeExr(const std::filesystem::path& path, const Image& image, const ExrWriteOptions& options) {
    exr_checks::checkWriteOptions(path, image, options);
    try {
        Imf::Header header(int(image.width()), int(image.height()));
        header.compression() = toImf(options.compression);
        Imf::FrameBuffer frameBuffer;
        // OpenEXR converts pixel types when reading but not when writing: half channels are
        // converted here (round to nearest; beyond 65504 becomes Inf).
        std::vector<std::vector<half>> halfPlanes;
        halfPlanes.reserve(image.channelCount());
        for (const std::string& name : image.channelNames()) {
            std::span<const float> plane = image.channel(name);
            if (exr_checks::typeFor(name, options) == ExrPixelType::Half) {
                header.channels().insert(name, Imf::Channel(Imf::HALF));
                std::vector<half>& converted = halfPlanes.emplace_back(plane.begin(), plane.end());
                frameBuffer.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(converted.data()),
                                                    sizeof(half), sizeof(half) * image.width()));
            } else {
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                // The writer only reads the plane.
                auto* base = reinterpret_cast<char*>(const_cast<float*>(plane.data()));
                frameBuffer.insert(
                    name, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * image.width()));
            }
        }
        Imf::OutputFile file(fileName(path).c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(int(image.height()));
    } catch (const std::exception& error) {
        fail(path, std::string("cannot write EXR: ") + error.what());
    }
}

} // namespace lumina::image
