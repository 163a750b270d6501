#include "tests/golden/golden.h"

#include "gi/image/png.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace lumina::test {

namespace {

// Debian 12's lavapipe, the one driver goldens are made on (docs/architecture.md, "Tests").
constexpr std::string_view kGoldenAdapter = "llvmpipe";
constexpr std::string_view kGoldenDriver = "Mesa 22.3.6";

image::Image preview(const image::Image& source, float lo, float hi) {
    const std::vector<std::string> names = source.channelNames();
    image::Image out = image::Image::rgb(source.width(), source.height());
    const char* rgb[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        // Images without R, G, B show their first channels (or the first one, grey).
        const std::string& from =
            source.hasRgb() ? std::string(rgb[c]) : names[std::min<size_t>(c, names.size() - 1)];
        const std::span<const float> values = source.channel(from);
        const std::span<float> to = out.channel(rgb[c]);
        for (size_t i = 0; i < values.size(); ++i) {
            const float t = (values[i] - lo) / (hi - lo);
            to[i] = t > 0.0f ? (t < 1.0f ? t : 1.0f) : 0.0f;
        }
    }
    return out;
}

std::string figures(const GoldenStats& stats, const GoldenTolerance& tolerance) {
    std::ostringstream out;
    out << "mean abs error " << stats.meanAbsError << " (tolerance " << tolerance.meanAbsError << "), "
        << tolerance.percentile * 100.0 << "th percentile " << stats.percentileError << " (tolerance "
        << tolerance.percentileError << "), max " << stats.maxError;
    return out.str();
}

// Writes the actual image, the expected one (when there is one) and the difference heat map.
std::string writeFailureEvidence(const GoldenSpec& spec, const image::Image& actual,
                                 const image::Image* expected, const GoldenStats* stats) {
    const std::filesystem::path dir = std::filesystem::absolute(goldenFailureDirectory());
    std::filesystem::create_directories(dir);
    std::vector<std::filesystem::path> written;
    written.push_back(dir / (spec.name + "_actual.exr"));
    image::writeExr(written.back(), actual);
    written.push_back(dir / (spec.name + "_actual.png"));
    image::writeDisplayPng(written.back(), preview(actual, spec.previewMin, spec.previewMax));
    if (expected) {
        written.push_back(dir / (spec.name + "_expected.png"));
        image::writeDisplayPng(written.back(), preview(*expected, spec.previewMin, spec.previewMax));
    }
    if (stats) {
        const float finiteMax = std::isfinite(stats->maxError) ? float(stats->maxError) : 1.0f;
        const float scale = std::max({finiteMax, float(spec.tolerance.percentileError), 1.0e-6f});
        written.push_back(dir / (spec.name + "_diff.png"));
        image::writeHeatmapPng(written.back(), stats->pixelErrors, actual.width(), actual.height(), scale);
    }
    std::string list = "\n  wrote:";
    for (const auto& path : written) {
        list += "\n    " + path.string();
    }
    return list;
}

} // namespace

GoldenStats compareWithGolden(const image::Image& golden, const image::Image& actual, double percentile) {
    image::requireSameSize(golden, actual, "golden vs actual");
    GoldenStats stats;
    stats.pixelErrors.assign(golden.pixelCount(), 0.0f);
    double sum = 0.0;
    const std::vector<std::string> channels = golden.channelNames();
    for (const std::string& name : channels) {
        const std::span<const float> expected = golden.channel(name);
        const std::span<const float> got = actual.channel(name);
        for (size_t i = 0; i < expected.size(); ++i) {
            float error = std::abs(got[i] - expected[i]);
            if (std::isnan(error)) {
                error = std::numeric_limits<float>::infinity();
            }
            sum += error;
            stats.pixelErrors[i] = std::max(stats.pixelErrors[i], error);
        }
    }
    stats.meanAbsError = sum / double(golden.pixelCount() * channels.size());
    std::vector<float> sorted = stats.pixelErrors;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = size_t(std::ceil(std::clamp(percentile, 0.0, 1.0) * double(sorted.size())));
    stats.percentileError = sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
    stats.maxError = sorted.back();
    return stats;
}

bool goldenUpdateAllowed(const rhi::AdapterInfo& adapter, std::string& why) {
    if (adapter.name.find(kGoldenAdapter) != std::string::npos &&
        adapter.driver.find(kGoldenDriver) != std::string::npos) {
        return true;
    }
    why = "goldens are made only on Debian 12's lavapipe (" + std::string(kGoldenAdapter) + ", " +
          std::string(kGoldenDriver) + "); this device is '" + adapter.name + "', driver '" + adapter.driver +
          "'";
    return false;
}

bool goldenUpdateRequested() {
    const char* value = std::getenv("LUMINA_UPDATE_GOLDENS");
    return value && std::string_view(value) == "1";
}

std::filesystem::path goldenDataDirectory() {
    if (const char* source = std::getenv("LUMINA_SOURCE_DIR"); source && *source) {
        return std::filesystem::path(source) / "tests" / "golden" / "data";
    }
    return std::filesystem::path(LUMINA_GOLDEN_SOURCE_DIR) / "data";
}

std::filesystem::path goldenFailureDirectory() {
    return std::filesystem::current_path() / "golden_failures";
}

GoldenResult checkGolden(const GoldenSpec& spec, const image::Image& actual,
                         const rhi::AdapterInfo& adapter) {
    GoldenResult result;
    const std::filesystem::path path = goldenDataDirectory() / (spec.name + ".exr");
    if (goldenUpdateRequested()) {
        std::string why;
        if (!goldenUpdateAllowed(adapter, why)) {
            result.message = "golden '" + spec.name + "': LUMINA_UPDATE_GOLDENS=1 refused: " + why;
            return result;
        }
        std::filesystem::create_directories(path.parent_path());
        image::ExrWriteOptions options;
        options.pixelType = spec.pixelType;
        image::writeExr(path, actual, options);
        const std::filesystem::path png = goldenDataDirectory() / (spec.name + ".png");
        image::writeDisplayPng(png, preview(actual, spec.previewMin, spec.previewMax));
        result.passed = true;
        result.updated = true;
        result.message = "golden '" + spec.name + "': wrote " + path.string() + " and " + png.string();
        return result;
    }
    if (!std::filesystem::exists(path)) {
        result.message = "golden '" + spec.name + "': no golden at " + path.string() +
                         " (make it with LUMINA_UPDATE_GOLDENS=1 ctest -L golden on Debian 12's lavapipe)" +
                         writeFailureEvidence(spec, actual, nullptr, nullptr);
        return result;
    }
    const image::Image golden = image::readExr(path);
    if (!golden.sameSize(actual)) {
        result.message = "golden '" + spec.name + "': " + path.string() + " is " + image::sizeString(golden) +
                         ", the image is " + image::sizeString(actual) +
                         writeFailureEvidence(spec, actual, &golden, nullptr);
        return result;
    }
    result.stats = compareWithGolden(golden, actual, spec.tolerance.percentile);
    result.passed = result.stats.meanAbsError <= spec.tolerance.meanAbsError &&
                    result.stats.percentileError <= spec.tolerance.percentileError;
    result.message =
        "golden '" + spec.name + "' (" + path.string() + "): " + figures(result.stats, spec.tolerance);
    if (!result.passed) {
        result.message += writeFailureEvidence(spec, actual, &golden, &result.stats);
    }
    return result;
}

} // namespace lumina::test
