#include "gi/measure/compare.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

namespace lumina::measure {

namespace {

// PSNR over the pixels finite in both linear images: a NaN pixel turned black by the display
// transform must not count as agreement.
double displayPsnr(const image::Image& reference, const image::Image& test,
                   const image::Image& referenceDisplay, const image::Image& testDisplay) {
    std::vector<bool> finite(reference.pixelCount(), true);
    for (const image::Image* image : {&reference, &test}) {
        for (const char* name : {"R", "G", "B"}) {
            std::span<const float> plane = image->channel(name);
            for (size_t i = 0; i < plane.size(); ++i) {
                if (!std::isfinite(plane[i])) {
                    finite[i] = false;
                }
            }
        }
    }
    double sum = 0.0;
    uint64_t samples = 0;
    for (const char* name : {"R", "G", "B"}) {
        std::span<const float> r = referenceDisplay.channel(name);
        std::span<const float> x = testDisplay.channel(name);
        for (size_t i = 0; i < r.size(); ++i) {
            if (finite[i]) {
                const double d = double(x[i]) - double(r[i]);
                sum += d * d;
                ++samples;
            }
        }
    }
    const double mse = samples == 0 ? 0.0 : sum / double(samples);
    return mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(1.0 / mse);
}

nlohmann::json counts(const NonFiniteCounts& c) {
    return {{"nan_pixels", c.nanPixels}, {"inf_pixels", c.infPixels}};
}

nlohmann::json finiteOrNull(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

} // namespace

CompareResult compareImages(const image::Image& reference, const image::Image& test,
                            const CompareOptions& options) {
    image::requireSameSize(reference, test, "reference vs test");
    CompareResult result;
    result.width = reference.width();
    result.height = reference.height();
    result.linear = errorStats(reference, test); // checks R, G, B
    result.reference = countNonFinite(reference);
    result.test = countNonFinite(test);
    const image::Image referenceDisplay = image::toDisplay(reference, options.display);
    const image::Image testDisplay = image::toDisplay(test, options.display);
    result.psnr = displayPsnr(reference, test, referenceDisplay, testDisplay);
    result.flip = flip(referenceDisplay, testDisplay, options.flip);
    return result;
}

std::string compareReportJson(const CompareResult& result, const std::string& referenceName,
                              const std::string& testName, const CompareOptions& options) {
    nlohmann::json json = {
        {"reference", referenceName},
        {"test", testName},
        {"width", result.width},
        {"height", result.height},
        {"compared_pixels", result.linear.pixels},
        {"relmse", result.linear.relMse},
        {"relmse_epsilon", kRelMseEpsilon},
        {"mse", result.linear.mse},
        {"rmse", result.linear.rmse},
        {"psnr_db", finiteOrNull(result.psnr)},
        {"psnr_peak", 1.0},
        {"max_error",
         {{"metric", "relmse"},
          {"value", result.linear.maxRelMse.value},
          {"x", result.linear.maxRelMse.x},
          {"y", result.linear.maxRelMse.y}}},
        {"flip",
         {{"mean", result.flip.mean},
          {"max", result.flip.max},
          {"max_x", result.flip.maxX},
          {"max_y", result.flip.maxY},
          {"pixels_per_degree", options.flip.pixelsPerDegree}}},
        {"display",
         {{"exposure_ev", options.display.exposureEv},
          {"tonemap", options.display.tonemap == image::Tonemap::AcesFitted ? "aces-fitted" : "clamp"}}},
        {"nonfinite", {{"reference", counts(result.reference)}, {"test", counts(result.test)}}},
        {"ok", !result.hasNonFinite()},
    };
    return json.dump(2) + "\n";
}

} // namespace lumina::measure
