#pragma once
// Pixel metrics between a reference and a test image, on their R, G, B channels.
//
//   relMSE = mean over pixels and R,G,B of (x - r)^2 / (r^2 + 0.01)   linear radiance
//   MSE    = mean over pixels and R,G,B of (x - r)^2;  RMSE = sqrt(MSE)
//   PSNR   = 10 log10(peak^2 / MSE) dB; +Inf when MSE is 0
//
// Pixels where either image has a non-finite R, G or B are left out of every mean (and
// counted by countNonFinite: any such pixel makes a comparison fail). Sizes must match
// (ImageError otherwise).
#include "gi/image/image.h"

#include <cstdint>
#include <vector>

namespace lumina::measure {

// The epsilon of relMSE: keeps dark reference pixels from dominating the mean.
inline constexpr double kRelMseEpsilon = 0.01;

struct NonFiniteCounts {
    uint64_t nanPixels = 0; // a pixel with any NaN in R, G, B
    uint64_t infPixels = 0; // a pixel with no NaN but some +-Inf in R, G, B
    uint64_t total() const { return nanPixels + infPixels; }
};

NonFiniteCounts countNonFinite(const image::Image& image);

struct PixelError {
    double value = 0.0;
    uint32_t x = 0;
    uint32_t y = 0;
};

struct ErrorStats {
    uint64_t pixels = 0; // pixels finite in both images, the ones averaged
    double relMse = 0.0;
    double mse = 0.0;
    double rmse = 0.0;
    PixelError maxRelMse; // the pixel with the largest relMSE (mean over its R, G, B)
};

ErrorStats errorStats(const image::Image& reference, const image::Image& test);

double relMse(const image::Image& reference, const image::Image& test);
double rmse(const image::Image& reference, const image::Image& test);
// On whatever encoding the images hold; the compare tool uses display-encoded sRGB, peak 1.
double psnr(const image::Image& reference, const image::Image& test, double peak = 1.0);

// Per-pixel relMSE (mean over R, G, B), row-major; NaN where either pixel is not finite.
std::vector<float> relMseMap(const image::Image& reference, const image::Image& test);

} // namespace lumina::measure
