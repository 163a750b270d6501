#pragma once
// 8-bit PNG output: tonemapped images (RGB, no alpha) and false-colour heat maps.
// Values are quantised as round(255 * v) after clamping to [0,1]. Failures are ImageErrors
// naming the file.
#include "gi/image/display.h"
#include "gi/image/image.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace lumina::image {

// A linear HDR image through the display transform (exposure, ACES fit, sRGB OETF).
void writePng(const std::filesystem::path& path, const Image& linear, const DisplayOptions& options = {});

// An image whose R, G, B are already display-encoded in [0,1] (e.g. from toDisplay).
void writeDisplayPng(const std::filesystem::path& path, const Image& display);

// A heat map of `values` (width*height, row-major): magma(value / maxValue); non-finite values
// are drawn in kHeatmapInvalid. maxValue must be positive.
void writeHeatmapPng(const std::filesystem::path& path, std::span<const float> values, uint32_t width,
                     uint32_t height, float maxValue = 1.0f);

} // namespace lumina::image
