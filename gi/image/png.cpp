#include "gi/image/png.h"

#include "gi/image/colormap.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

// Static linkage keeps stb's symbols private to this file (tinygltf and others bundle it too).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

namespace lumina::image {

namespace {

constexpr int kRgbComponents = 3;

uint8_t quantise(float v) {
    const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; // NaN -> 0
    return uint8_t(std::lround(clamped * 255.0f));
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

void writeRgb8(const std::filesystem::path& path, const std::vector<uint8_t>& pixels, uint32_t width,
               uint32_t height) {
    std::vector<uint8_t> encoded;
    if (stbi_write_png_to_func(appendBytes, &encoded, int(width), int(height), kRgbComponents, pixels.data(),
                               int(width) * kRgbComponents) == 0 ||
        encoded.empty()) {
        throw ImageError(path.string() + ": PNG encoding failed");
    }
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) {
        throw ImageError(path.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
    }
    file.write(reinterpret_cast<const char*>(encoded.data()), std::streamsize(encoded.size()));
    file.close();
    if (!file) {
        throw ImageError(path.string() + ": write failed (" + std::strerror(errno) + ")");
    }
}

void checkWritable(const std::filesystem::path& path, const Image& image) {
    if (image.empty()) {
        throw ImageError(path.string() + ": cannot write an empty image");
    }
    if (!image.hasRgb()) {
        throw ImageError(path.string() + ": the image has no R, G, B channels to write");
    }
}

} // namespace

void writeDisplayPng(const std::filesystem::path& path, const Image& display) {
    checkWritable(path, display);
    std::span<const float> r = display.channel("R");
    std::span<const float> g = display.channel("G");
    std::span<const float> b = display.channel("B");
    std::vector<uint8_t> pixels(display.pixelCount() * kRgbComponents);
    for (size_t i = 0; i < display.pixelCount(); ++i) {
        pixels[i * 3 + 0] = quantise(r[i]);
        pixels[i * 3 + 1] = quantise(g[i]);
        pixels[i * 3 + 2] = quantise(b[i]);
    }
    writeRgb8(path, pixels, display.width(), display.height());
}

void writePng(const std::filesystem::path& path, const Image& linear, const DisplayOptions& options) {
    checkWritable(path, linear);
    writeDisplayPng(path, toDisplay(linear, options));
}

void writeHeatmapPng(const std::filesystem::path& path, std::span<const float> values, uint32_t width,
                     uint32_t height, float maxValue) {
    if (width == 0 || height == 0 || values.size() != size_t(width) * height) {
        throw ImageError(path.string() + ": heat map of " + std::to_string(values.size()) +
                         " values does not match " + std::to_string(width) + "x" + std::to_string(height));
    }
    if (!(maxValue > 0.0f) || !std::isfinite(maxValue)) {
        throw ImageError(path.string() + ": heat map maximum must be a positive finite number");
    }
    std::vector<uint8_t> pixels(values.size() * kRgbComponents);
    for (size_t i = 0; i < values.size(); ++i) {
        const Rgb8 colour = std::isfinite(values[i]) ? magma(values[i] / maxValue) : kHeatmapInvalid;
        pixels[i * 3 + 0] = colour[0];
        pixels[i * 3 + 1] = colour[1];
        pixels[i * 3 + 2] = colour[2];
    }
    writeRgb8(path, pixels, width, height);
}

} // namespace lumina::image
