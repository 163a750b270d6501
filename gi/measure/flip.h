#pragma once
// LDR-FLIP (Andersson et al., HPG 2020): a per-pixel perceptual difference in [0,1] between
// two display-encoded sRGB images, as seen by an observer at a given number of pixels per
// degree of visual angle, and its mean. Implemented from the paper; see docs/measurement.md.
#include "gi/image/image.h"

#include <cstdint>
#include <vector>

namespace lumina::measure {

// Pixels per degree for a viewer `distance` metres from a monitor `monitorWidth` metres wide
// showing `horizontalPixels` pixels: distance * (pixels / width) * pi / 180.
double pixelsPerDegree(double distance, double monitorWidth, double horizontalPixels);

// FLIP's default observer: 0.7 m from a 0.7 m wide 3840-pixel (4K) monitor, about 67 ppd.
inline constexpr double kDefaultPixelsPerDegree = 0.7 * (3840.0 / 0.7) * 3.14159265358979323846 / 180.0;

struct FlipOptions {
    double pixelsPerDegree = kDefaultPixelsPerDegree; // [1, 1000]
    bool keepComponents = false;                      // also return the colour-only and feature-only maps
};

struct FlipResult {
    uint32_t width = 0;
    uint32_t height = 0;
    double mean = 0.0; // mean of errorMap
    float max = 0.0f;  // largest value of errorMap, at (maxX, maxY)
    uint32_t maxX = 0;
    uint32_t maxY = 0;
    std::vector<float> errorMap;   // Delta E per pixel, row-major, in [0,1]
    std::vector<float> colorMap;   // Delta E_c (keepComponents only)
    std::vector<float> featureMap; // Delta E_f (keepComponents only)
};

// Both images hold R, G, B display-encoded sRGB in [0,1] (e.g. image::toDisplay of linear
// radiance); values outside [0,1] are clamped and NaN reads as 0. ImageError when a channel is
// missing or the sizes differ.
FlipResult flip(const image::Image& referenceSrgb, const image::Image& testSrgb,
                const FlipOptions& options = {});

} // namespace lumina::measure
