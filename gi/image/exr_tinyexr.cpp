// gi/image/exr.h with tinyexr (Debian's libtinyexr-dev: one header, zlib for ZIP), for builds
// without OpenEXR: the MinGW-w64 cross build, where Debian has no OpenEXR but has zlib
// (libz-mingw-w64-dev). Same contract as exr_openexr.cpp: scanline or tiled (level 0),
// half, float and uint channels, None/ZIP/PIZ written; the shared checks in exr_checks.h.
#include "gi/image/exr.h"

#include "gi/image/exr_checks.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>

namespace lumina::image {

namespace {

using exr_checks::fail;
using exr_checks::Window;

// tinyexr takes UTF-8 names on every system (it widens them itself on Windows).
std::string utf8Name(const std::filesystem::path& path) {
    const std::u8string name = path.u8string();
    return std::string(name.begin(), name.end());
}

// tinyexr's error strings are allocated; this takes ownership and returns a copy.
std::string takeError(const char* error, int code) {
    std::string text = error ? error : "tinyexr error " + std::to_string(code);
    if (error) {
        FreeEXRErrorMessage(error);
    }
    return text;
}

const char* pixelTypeName(int type) {
    switch (type) {
    case TINYEXR_PIXELTYPE_HALF:
        return "half";
    case TINYEXR_PIXELTYPE_FLOAT:
        return "float";
    case TINYEXR_PIXELTYPE_UINT:
        return "uint";
    default:
        return "unknown";
    }
}

Window toWindow(const EXRBox2i& box) {
    return {box.min_x, box.min_y, box.max_x, box.max_y};
}

// A parsed header, freed with its owner.
class Header {
public:
    explicit Header(const std::filesystem::path& path) {
        exr_checks::checkFileExists(path);
        InitEXRHeader(&header_);
        EXRVersion version;
        if (ParseEXRVersionFromFile(&version, utf8Name(path).c_str()) != TINYEXR_SUCCESS) {
            fail(path, "not an OpenEXR file (or unreadable)");
        }
        if (version.non_image) {
            fail(path, "deep OpenEXR images are not supported");
        }
        if (version.multipart) {
            fail(path, "multi-part OpenEXR files are not supported");
        }
        const char* error = nullptr;
        const int code = ParseEXRHeaderFromFile(&header_, &version, utf8Name(path).c_str(), &error);
        if (code != TINYEXR_SUCCESS) {
            // tinyexr fills the header's arrays even when parsing fails (found by the fuzzer,
            // tests/fuzz/regressions/exr_tinyexr/header_leak): free them before throwing.
            const std::string problem = takeError(error, code);
            FreeEXRHeader(&header_);
            fail(path, "cannot read EXR header: " + problem);
        }
        parsed_ = true;
    }
    ~Header() {
        if (parsed_) {
            FreeEXRHeader(&header_);
        }
    }
    Header(const Header&) = delete;
    Header& operator=(const Header&) = delete;

    EXRHeader& get() { return header_; }
    std::vector<std::string> channelNames() const {
        std::vector<std::string> names;
        for (int c = 0; c < header_.num_channels; ++c) {
            names.emplace_back(header_.channels[c].name);
        }
        return names;
    }

private:
    EXRHeader header_;
    bool parsed_ = false;
};

// One channel's value at `index` of a decoded plane, as float (half was decoded to float).
float valueAt(const unsigned char* plane, int pixelType, size_t index) {
    if (pixelType == TINYEXR_PIXELTYPE_UINT) {
        uint32_t value;
        std::memcpy(&value, plane + index * sizeof(uint32_t), sizeof(value));
        return float(value);
    }
    float value;
    std::memcpy(&value, plane + index * sizeof(float), sizeof(value));
    return value;
}

// Copies the decoded planes (scanline: one data-window image; tiled: level-0 tiles, each
// tile_size_x wide in memory) into data-window planes in `order`.
std::vector<std::vector<float>> dataPlanes(const EXRHeader& header, const EXRImage& decoded,
                                           const Window& data, const std::vector<std::string>& order) {
    const size_t width = size_t(data.width());
    std::vector<std::vector<float>> planes(order.size(),
                                           std::vector<float>(width * size_t(data.height()), 0.0f));
    for (size_t c = 0; c < order.size(); ++c) {
        int fileIndex = 0;
        while (order[c] != header.channels[fileIndex].name) {
            ++fileIndex;
        }
        const int type = header.requested_pixel_types[fileIndex];
        std::vector<float>& out = planes[c];
        if (!header.tiled) {
            for (size_t i = 0; i < out.size(); ++i) {
                out[i] = valueAt(decoded.images[fileIndex], type, i);
            }
            continue;
        }
        for (int t = 0; t < decoded.num_tiles; ++t) {
            const EXRTile& tile = decoded.tiles[t];
            const size_t x0 = size_t(tile.offset_x) * size_t(header.tile_size_x);
            const size_t y0 = size_t(tile.offset_y) * size_t(header.tile_size_y);
            for (int y = 0; y < tile.height; ++y) {
                for (int x = 0; x < tile.width; ++x) {
                    const size_t at = (y0 + size_t(y)) * width + x0 + size_t(x);
                    if (at < out.size()) {
                        out[at] = valueAt(tile.images[fileIndex], type,
                                          size_t(y) * size_t(header.tile_size_x) + size_t(x));
                    }
                }
            }
        }
    }
    return planes;
}

// tinyexr 1.0.1's PIZ decoder copies the bitmap range a chunk declares (up to 8 KiB) without
// checking that the chunk holds it, reading past the end of the file's bytes (found by the
// tinyexr fuzzer, tests/fuzz/regressions/exr_tinyexr/piz_bitmap_*). The pixels are decoded from
// the file's bytes followed by this many zeros, so that such a read stays in memory of ours; the
// size tinyexr is given, and so every check it does make, is the file's own.
constexpr size_t kPizOverreadPadding = 64 * 1024;

std::vector<unsigned char> fileBytesWithPadding(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.eof() && in.fail()) {
        fail(path, "cannot read the file");
    }
    return bytes;
}

Image readPixels(const std::filesystem::path& path) {
    Header parsed(path);
    EXRHeader& header = parsed.get();
    const Window display = toWindow(header.display_window);
    const Window data = toWindow(header.data_window);
    exr_checks::checkWindow(path, display, "display");
    exr_checks::checkWindow(path, data, "data");
    const std::vector<std::string> fileChannels = parsed.channelNames();
    exr_checks::checkHasRgb(path, fileChannels);
    for (int c = 0; c < header.num_channels; ++c) {
        if (header.channels[c].x_sampling > 1 || header.channels[c].y_sampling > 1) {
            fail(path, "channel '" + std::string(header.channels[c].name) +
                           "' is subsampled, which is not supported");
        }
        // tinyexr converts half to float while decoding; float and uint stay as they are.
        if (header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
            header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }

    EXRImage decoded;
    InitEXRImage(&decoded);
    // On a failed decode tinyexr calls FreeEXRImage, which frees the channels' planes up to
    // num_channels, set only on success: set first, a truncated file's planes are freed too
    // (LeakSanitizer found it: Exr.TruncatedFileIsAnErrorNotACrash in .ci/sanitizers.sh).
    decoded.num_channels = header.num_channels;
    const char* error = nullptr;
    std::vector<unsigned char> bytes = fileBytesWithPadding(path);
    const size_t fileSize = bytes.size();
    bytes.resize(fileSize + kPizOverreadPadding, 0);
    const int code = LoadEXRImageFromMemory(&decoded, &header, bytes.data(), fileSize, &error);
    if (code != TINYEXR_SUCCESS) {
        // tinyexr has freed what it decoded (FreeEXRImage again would free it twice).
        fail(path, "cannot read EXR: " + takeError(error, code));
    }
    const std::vector<std::string> order = exr_checks::readOrder(fileChannels);
    std::vector<std::vector<float>> planes;
    try {
        planes = dataPlanes(header, decoded, data, order);
    } catch (...) {
        FreeEXRImage(&decoded);
        throw;
    }
    FreeEXRImage(&decoded);
    return exr_checks::placeInDisplayWindow(display, data, order, planes);
}

int toTinyexr(ExrCompression compression) {
    switch (compression) {
    case ExrCompression::None:
        return TINYEXR_COMPRESSIONTYPE_NONE;
    case ExrCompression::Piz:
        return TINYEXR_COMPRESSIONTYPE_PIZ;
    case ExrCompression::Zip:
        break;
    }
    return TINYEXR_COMPRESSIONTYPE_ZIP;
}

} // namespace

ExrInfo readExrInfo(const std::filesystem::path& path) {
    Header parsed(path);
    const EXRHeader& header = parsed.get();
    const Window display = toWindow(header.display_window);
    ExrInfo info;
    info.width = uint32_t(std::max<int64_t>(display.width(), 0));
    info.height = uint32_t(std::max<int64_t>(display.height(), 0));
    info.tiled = header.tiled != 0;
    for (int c = 0; c < header.num_channels; ++c) {
        info.channels.push_back({header.channels[c].name, pixelTypeName(header.pixel_types[c])});
    }
    return info;
}

Image readExr(const std::filesystem::path& path) {
    return exr_checks::readReportingErrors(path, [&] { return readPixels(path); });
}

void writeExr(const std::filesystem::path& path, const Image& image, const ExrWriteOptions& options) {
    exr_checks::checkWriteOptions(path, image, options);
    // OpenEXR files list channels in alphabetical (byte) order; readers expect it.
    std::vector<std::string> names = image.channelNames();
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) {
        if (name.size() > 255) {
            fail(path, "channel name '" + name + "' is longer than 255 bytes");
        }
    }
    const int count = int(names.size());
    std::vector<EXRChannelInfo> channels(names.size());
    std::vector<int> inputTypes(names.size(), TINYEXR_PIXELTYPE_FLOAT);
    std::vector<int> storedTypes(names.size());
    std::vector<unsigned char*> planes(names.size());
    for (size_t c = 0; c < names.size(); ++c) {
        std::memset(&channels[c], 0, sizeof(EXRChannelInfo));
        std::memcpy(channels[c].name, names[c].c_str(), names[c].size() + 1);
        channels[c].x_sampling = 1;
        channels[c].y_sampling = 1;
        // tinyexr converts float input to half when writing (round to nearest; beyond 65504 is Inf).
        storedTypes[c] = exr_checks::typeFor(names[c], options) == ExrPixelType::Half
                             ? TINYEXR_PIXELTYPE_HALF
                             : TINYEXR_PIXELTYPE_FLOAT;
        channels[c].pixel_type = storedTypes[c];
        // The writer only reads the planes.
        planes[c] = reinterpret_cast<unsigned char*>(const_cast<float*>(image.channel(names[c]).data()));
    }

    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = count;
    header.channels = channels.data();
    header.pixel_types = inputTypes.data();
    header.requested_pixel_types = storedTypes.data();
    header.compression_type = toTinyexr(options.compression);
    header.data_window = {0, 0, int(image.width()) - 1, int(image.height()) - 1};
    header.display_window = header.data_window;
    header.pixel_aspect_ratio = 1.0f;
    header.screen_window_width = 1.0f;

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.images = planes.data();
    exrImage.width = int(image.width());
    exrImage.height = int(image.height());
    exrImage.num_channels = count;

    const char* error = nullptr;
    const int code = SaveEXRImageToFile(&exrImage, &header, utf8Name(path).c_str(), &error);
    if (code != TINYEXR_SUCCESS) {
        fail(path, "cannot write EXR: " + takeError(error, code));
    }
}

} // namespace lumina::image
