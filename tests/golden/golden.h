#pragma once
// Golden images (docs/goldens.md): a rendered image compared with a stored one under a stated
// tolerance, with the evidence of a failure written where it can be looked at.
//
//   const GoldenResult result = checkGolden({.name = "cornell_box_point_albedo"}, image, adapter);
//   EXPECT_TRUE(result.passed) << result.message;
//
// Goldens are EXR files under tests/golden/data/ (plus a PNG preview for review). The compare
// takes every channel of the golden: the mean absolute error over all values, and a
// percentile (99th by default) of the per-pixel error (largest over the pixel's channels),
// each against its tolerance, so that a handful of edge pixels may differ but no region.
//
// A failing check writes <name>_actual.exr/.png, <name>_expected.png and <name>_diff.png (heat
// map of the per-pixel error) into golden_failures/ under the working directory and names
// them in its message. With LUMINA_UPDATE_GOLDENS=1 the check writes the golden instead, and
// only on Debian 12's lavapipe (llvmpipe, Mesa 22.3.6); anywhere else it fails, saying why.
#include "gi/image/exr.h"
#include "gi/image/image.h"
#include "rhi/device.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lumina::test {

struct GoldenTolerance {
    double meanAbsError = 0.002;   // mean of |actual - golden| over every pixel and channel
    double percentile = 0.99;      // which per-pixel error is bounded by percentileError
    double percentileError = 0.02; // that percentile of max-over-channels |actual - golden|
};

struct GoldenSpec {
    std::string name; // file stem under tests/golden/data/
    GoldenTolerance tolerance{};
    image::ExrPixelType pixelType = image::ExrPixelType::Half; // how the golden is stored
    // A [0,1] display view for the PNG previews: values mapped from [previewMin, previewMax].
    float previewMin = 0.0f;
    float previewMax = 1.0f;
};

struct GoldenStats {
    double meanAbsError = 0.0;
    double percentileError = 0.0;
    double maxError = 0.0;
    std::vector<float> pixelErrors; // per pixel, max over the compared channels
};

// Compares the golden's channels (all of which `actual` must have, at the same size; an
// ImageError otherwise). NaN in either image counts as an infinite error.
GoldenStats compareWithGolden(const image::Image& golden, const image::Image& actual, double percentile);

struct GoldenResult {
    bool passed = false;
    bool updated = false; // LUMINA_UPDATE_GOLDENS=1 wrote the golden
    GoldenStats stats;
    std::string message; // what was compared, the figures, and any files written
};

GoldenResult checkGolden(const GoldenSpec& spec, const image::Image& actual, const rhi::AdapterInfo& adapter);

// Whether goldens may be written on this adapter (Debian 12's lavapipe); `why` says otherwise.
bool goldenUpdateAllowed(const rhi::AdapterInfo& adapter, std::string& why);
// LUMINA_UPDATE_GOLDENS=1 in the environment.
bool goldenUpdateRequested();

// $LUMINA_SOURCE_DIR/tests/golden/data, else the source tree this was built from.
std::filesystem::path goldenDataDirectory();
// golden_failures/ under the working directory.
std::filesystem::path goldenFailureDirectory();

} // namespace lumina::test
