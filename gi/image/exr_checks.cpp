#include "gi/image/exr_checks.h"

#include <algorithm>
#include <exception>
#include <new>
#include <system_error>

namespace lumina::image::exr_checks {

void fail(const std::filesystem::path& path, const std::string& problem) {
    throw ImageError(path.string() + ": " + problem);
}

void checkFileExists(const std::filesystem::path& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) {
        fail(path, "file not found");
    }
    if (std::filesystem::is_directory(status)) {
        fail(path, "is a directory, not an EXR file");
    }
}

void checkWindow(const std::filesystem::path& path, const Window& window, const char* which) {
    if (window.width() <= 0 || window.height() <= 0 || window.width() > kMaxImageSide ||
        window.height() > kMaxImageSide ||
        uint64_t(window.width()) * uint64_t(window.height()) > kMaxImagePixels) {
        fail(path, std::string(which) + " window " + std::to_string(window.width()) + "x" +
                       std::to_string(window.height()) + " is empty or too large");
    }
}

void checkHasRgb(const std::filesystem::path& path, const std::vector<std::string>& channels) {
    std::string missing;
    for (const char* name : {"R", "G", "B"}) {
        if (std::find(channels.begin(), channels.end(), name) == channels.end()) {
            missing += missing.empty() ? name : std::string(", ") + name;
        }
    }
    if (missing.empty()) {
        return;
    }
    std::string present;
    for (const std::string& name : channels) {
        present += (present.empty() ? "" : ", ") + name;
    }
    fail(path,
         "missing channel(s) " + missing + " (the file has: " + (present.empty() ? "none" : present) + ")");
}

std::vector<std::string> readOrder(const std::vector<std::string>& fileChannels) {
    std::vector<std::string> order;
    for (const char* name : {"R", "G", "B", "A"}) {
        if (std::find(fileChannels.begin(), fileChannels.end(), name) != fileChannels.end()) {
            order.emplace_back(name);
        }
    }
    for (const std::string& name : fileChannels) {
        if (std::find(order.begin(), order.end(), name) == order.end()) {
            order.push_back(name);
        }
    }
    return order;
}

Image placeInDisplayWindow(const Window& display, const Window& data, const std::vector<std::string>& order,
                           const std::vector<std::vector<float>>& planes) {
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

Image readReportingErrors(const std::filesystem::path& path, const std::function<Image()>& read) {
    try {
        return read();
    } catch (const ImageError&) {
        throw;
    } catch (const std::bad_alloc&) {
        fail(path, "out of memory reading the image");
    } catch (const std::exception& error) {
        fail(path, std::string("cannot read EXR: ") + error.what());
    }
}

void checkWriteOptions(const std::filesystem::path& path, const Image& image,
                       const ExrWriteOptions& options) {
    if (image.empty() || image.channelCount() == 0) {
        fail(path, "cannot write an empty image");
    }
    for (const auto& [channel, type] : options.channelTypes) {
        if (!image.hasChannel(channel)) {
            fail(path, "a pixel type is given for channel '" + channel + "', which the image does not have");
        }
    }
}

ExrPixelType typeFor(const std::string& name, const ExrWriteOptions& options) {
    for (const auto& [channel, type] : options.channelTypes) {
        if (channel == name) {
            return type;
        }
    }
    return options.pixelType;
}

} // namespace lumina::image::exr_checks

namespace lumina::image {

const char* exrPixelTypeName(ExrPixelType type) {
    return type == ExrPixelType::Half ? "half" : "float";
}

} // namespace lumina::image
