#include "gi/image/exr.h"

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTestFile.h>
#include <algorithm>
#include <exception>
#include <half.h>
#include <system_error>

namespace lumina::image {

namespace {

std::string fileName(const std::filesystem::path& path) {
    return path.string();
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
    throw ImageError(fileName(path) + ": " + problem);
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
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) {
        fail(path, "file not found");
    }
    if (std::filesystem::is_directory(status)) {
        fail(path, "is a directory, not an EXR file");
    }
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

struct Window {
    int minX, minY, maxX, maxY;
    int64_t width() const { return int64_t(maxX) - minX + 1; }
    int64_t height() const { return int64_t(maxY) - minY + 1; }
};

Window toWindow(const Imath::Box2i& box) {
    return {box.min.x, box.min.y, box.max.x, box.max.y};
}

void checkWindow(const std::filesystem::path& path, const Window& window, const char* which) {
    if (window.width() <= 0 || window.height() <= 0 || window.width() > kMaxImageSide ||
        window.height() > kMaxImageSide ||
        uint64_t(window.width()) * uint64_t(window.height()) > kMaxImagePixels) {
        fail(path, std::string(which) + " window " + std::to_string(window.width()) + "x" +
                       std::to_string(window.height()) + " is empty or too large");
    }
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

// R, G, B, A first, then the rest in the file's order.
std::vector<std::string> readOrder(const Imf::ChannelList& channels) {
    std::vector<std::string> order;
    for (const char* name : {"R", "G", "B", "A"}) {
        if (channels.findChannel(name)) {
            order.emplace_back(name);
        }
    }
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        if (std::find(order.begin(), order.end(), it.name()) == order.end()) {
            order.emplace_back(it.name());
        }
    }
    return order;
}

Image readPixels(const std::filesystem::path& path) {
    Imf::InputFile file(fileName(path).c_str());
    const Imf::Header& header = file.header();
    const Window display = toWindow(header.displayWindow());
    const Window data = toWindow(header.dataWindow());
    checkWindow(path, display, "display");
    checkWindow(path, data, "data");

    const Imf::ChannelList& channels = header.channels();
    std::string missing;
    for (const char* name : {"R", "G", "B"}) {
        if (!channels.findChannel(name)) {
            missing += missing.empty() ? name : std::string(", ") + name;
        }
    }
    if (!missing.empty()) {
        std::string present;
        for (auto it = channels.begin(); it != channels.end(); ++it) {
            present += (present.empty() ? "" : ", ") + std::string(it.name());
        }
        fail(path, "missing channel(s) " + missing +
                       " (the file has: " + (present.empty() ? "none" : present) + ")");
    }
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
            fail(path, "channel '" + std::string(it.name()) + "' is subsampled, which is not supported");
        }
    }

    // Read the data window into planes of its own size, then place it in the display window.
    const std::vector<std::string> order = readOrder(channels);
    const size_t dataPixels = size_t(data.width()) * size_t(data.height());
    std::vector<std::vector<float>> planes(order.size(), std::vector<float>(dataPixels, 0.0f));
    Imf::FrameBuffer frameBuffer;
    for (size_t c = 0; c < order.size(); ++c) {
        frameBuffer.insert(order[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), header.dataWindow(),
                                                      sizeof(float), sizeof(float) * size_t(data.width())));
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(data.minY, data.maxY);

    Image image(uint32_t(display.width()), uint32_t(display.height()), order);
    const int x0 = std::max(display.minX, data.minX);
    const int x1 = std::min(display.maxX, data.maxX);
    const int y0 = std::max(display.minY, data.minY);
    const int y1 = std::min(display.maxY, data.maxY);
    for (size_t c = 0; c < order.size(); ++c) {
        std::span<float> out = image.channel(order[c]);
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                out[size_t(y - display.minY) * image.width() + size_t(x - display.minX)] =
                    planes[c][size_t(y - data.minY) * size_t(data.width()) + size_t(x - data.minX)];
            }
        }
    }
    return image;
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

ExrPixelType typeFor(const std::string& name, const ExrWriteOptions& options) {
    for (const auto& [channel, type] : options.channelTypes) {
        if (channel == name) {
            return type;
        }
    }
    return options.pixelType;
}

} // namespace

const char* exrPixelTypeName(ExrPixelType type) {
    return type == ExrPixelType::Half ? "half" : "float";
}

ExrInfo readExrInfo(const std::filesystem::path& path) {
    checkReadable(path);
    try {
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
    try {
        return readPixels(path);
    } catch (const ImageError&) {
        throw;
    } catch (const std::bad_alloc&) {
        fail(path, "out of memory reading the image");
    } catch (const std::exception& error) {
        fail(path, std::string("cannot read EXR: ") + error.what());
    }
}

void writeExr(const std::filesystem::path& path, const Image& image, const ExrWriteOptions& options) {
    if (image.empty() || image.channelCount() == 0) {
        fail(path, "cannot write an empty image");
    }
    for (const auto& [channel, type] : options.channelTypes) {
        if (!image.hasChannel(channel)) {
            fail(path, "a pixel type is given for channel '" + channel + "', which the image does not have");
        }
    }
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
            if (typeFor(name, options) == ExrPixelType::Half) {
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
