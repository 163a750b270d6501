#pragma once
// One comparison of a test image against a reference, as `lumina compare` and the bench run it:
// linear-radiance metrics (relMSE, RMSE, worst pixel), display metrics (PSNR and LDR-FLIP on
// both images through the same display transform) and NaN/Inf counts.
#include "gi/image/display.h"
#include "gi/image/image.h"
#include "gi/measure/flip.h"
#include "gi/measure/metrics.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lumina::measure {

struct CompareOptions {
    image::DisplayOptions display; // applied to both images before PSNR and FLIP
    FlipOptions flip;
};

struct CompareResult {
    uint32_t width = 0;
    uint32_t height = 0;
    NonFiniteCounts reference;
    NonFiniteCounts test;
    ErrorStats linear; // relMSE, MSE, RMSE, worst relMSE pixel, on linear radiance
    double psnr = 0.0; // dB, display-encoded sRGB, peak 1; +Inf when identical there
    FlipResult flip;   // mean, max and error map
    // A NaN or Inf in either image: the comparison is invalid and tools must exit non-zero.
    bool hasNonFinite() const { return reference.total() != 0 || test.total() != 0; }
};

// ImageError when the sizes differ or R, G, B are missing. Non-finite pixels do not throw:
// they are counted, left out of the linear and PSNR means, and enter FLIP as the display
// transform maps them (NaN -> 0, +Inf -> 1).
CompareResult compareImages(const image::Image& reference, const image::Image& test,
                            const CompareOptions& options = {});

// The result as a JSON object (schema in docs/measurement.md); infinite PSNR is null.
std::string compareReportJson(const CompareResult& result, const std::string& referenceName,
                              const std::string& testName, const CompareOptions& options);

} // namespace lumina::measure
