#pragma once
// OpenEXR reading and writing (scanline or tiled, single part, flat images).
//
// readExr: any EXR with R, G and B channels (A and any other channels optional), whatever
// their pixel type (half, float or uint; all become float). The image has the size of the
// file's display window; pixels of the display window outside the data window are 0.
// Channels come back R, G, B, A first, then the others in the file's (alphabetical) order.
//
// writeExr: every channel of the image, each stored as half or float as the options say.
// Half holds 11 significant bits and a largest finite value of 65504 (larger values become
// +Inf): use float for references and anything compared exactly.
//
// Every failure is an ImageError whose message starts with the file name.
#include "gi/image/image.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace lumina::image {

enum class ExrPixelType { Half, Float };
enum class ExrCompression { None, Zip, Piz };

struct ExrWriteOptions {
    ExrPixelType pixelType = ExrPixelType::Float;                   // for every channel not named below
    std::vector<std::pair<std::string, ExrPixelType>> channelTypes; // per-channel overrides
    ExrCompression compression = ExrCompression::Zip;               // lossless either way
};

struct ExrChannelInfo {
    std::string name;
    std::string pixelType; // "half", "float" or "uint"
};

struct ExrInfo {
    uint32_t width = 0; // display window
    uint32_t height = 0;
    std::vector<ExrChannelInfo> channels; // the file's order (alphabetical)
    bool tiled = false;
};

// Header only: size and channels, without reading pixels.
ExrInfo readExrInfo(const std::filesystem::path& path);

// Every channel; ImageError when the file is missing, not an EXR, deep, subsampled, too
// large, damaged, or lacks any of R, G, B.
Image readExr(const std::filesystem::path& path);

void writeExr(const std::filesystem::path& path, const Image& image, const ExrWriteOptions& options = {});

const char* exrPixelTypeName(ExrPixelType type);

} // namespace lumina::image
