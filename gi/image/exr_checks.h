#pragma once
// What both EXR implementations (exr_openexr.cpp, exr_tinyexr.cpp) check and decide the same
// way, so that a file is accepted or refused with the same message whichever library reads it.
#include "gi/image/exr.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lumina::image::exr_checks {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem);

// Missing file or a directory: fails naming the file. (Whether it is an EXR is each library's.)
void checkFileExists(const std::filesystem::path& path);

// An inclusive pixel window as EXR headers store it.
struct Window {
    int minX, minY, maxX, maxY;
    int64_t width() const { return int64_t(maxX) - minX + 1; }
    int64_t height() const { return int64_t(maxY) - minY + 1; }
};

// Empty or beyond kMaxImageSide / kMaxImagePixels: fails naming the window ("display", "data").
void checkWindow(const std::filesystem::path& path, const Window& window, const char* which);

// Fails unless R, G and B are among `channels` (the message lists what the file has).
void checkHasRgb(const std::filesystem::path& path, const std::vector<std::string>& channels);

// R, G, B, A first, then the rest in the file's order.
std::vector<std::string> readOrder(const std::vector<std::string>& fileChannels);

// The image of the display window's size, with the data window's planes (one per name in
// `order`, data-window sized, row-major) placed where they belong and 0 elsewhere.
Image placeInDisplayWindow(const Window& display, const Window& data, const std::vector<std::string>& order,
                           const std::vector<std::vector<float>>& planes);

// Runs a library's read: ImageErrors pass; any other exception (the library's, out of
// memory) becomes an ImageError naming the file.
Image readReportingErrors(const std::filesystem::path& path, const std::function<Image()>& read);

// Fails when options name a channel the image lacks.
void checkWriteOptions(const std::filesystem::path& path, const Image& image, const ExrWriteOptions& options);

// The pixel type a channel is written with.
ExrPixelType typeFor(const std::string& name, const ExrWriteOptions& options);

} // namespace lumina::image::exr_checks
