#include "gi/measure/metrics.h"

#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace lumina::measure {

namespace {

struct RgbPlanes {
    std::span<const float> r, g, b;
    explicit RgbPlanes(const image::Image& image)
        : r(image.channel("R")), g(image.channel("G")), b(image.channel("B")) {}
    bool finite(size_t i) const { return std::isfinite(r[i]) && std::isfinite(g[i]) && std::isfinite(b[i]); }
};

void checkPair(const image::Image& reference, const image::Image& test) {
    image::requireSameSize(reference, test, "reference vs test");
    if (!reference.hasRgb() || !test.hasRgb()) {
        throw image::ImageError("reference vs test: both images need R, G, B channels");
    }
}

// Visits every pixel finite in both images with its three (reference, test) pairs.
template <typename Visit>
void forFinitePairs(const image::Image& reference, const image::Image& test, Visit&& visit) {
    checkPair(reference, test);
    const RgbPlanes ref(reference);
    const RgbPlanes tst(test);
    for (size_t i = 0; i < reference.pixelCount(); ++i) {
        if (ref.finite(i) && tst.finite(i)) {
            visit(i, std::array<double, 3>{ref.r[i], ref.g[i], ref.b[i]},
                  std::array<double, 3>{tst.r[i], tst.g[i], tst.b[i]});
        }
    }
}

double pixelRelMse(const std::array<double, 3>& r, const std::array<double, 3>& x) {
    double sum = 0.0;
    for (size_t c = 0; c < 3; ++c) {
        const double d = x[c] - r[c];
        sum += d * d / (r[c] * r[c] + kRelMseEpsilon);
    }
    return sum / 3.0;
}

} // namespace

NonFiniteCounts countNonFinite(const image::Image& image) {
    NonFiniteCounts counts;
    const RgbPlanes planes(image);
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        if (std::isnan(planes.r[i]) || std::isnan(planes.g[i]) || std::isnan(planes.b[i])) {
            ++counts.nanPixels;
        } else if (!planes.finite(i)) {
            ++counts.infPixels;
        }
    }
    return counts;
}

ErrorStats errorStats(const image::Image& reference, const image::Image& test) {
    ErrorStats stats;
    double relSum = 0.0;
    double sqSum = 0.0;
    stats.maxRelMse.value = -1.0;
    const uint32_t width = reference.width();
    forFinitePairs(reference, test, [&](size_t i, const auto& r, const auto& x) {
        const double rel = pixelRelMse(r, x);
        relSum += rel;
        for (size_t c = 0; c < 3; ++c) {
            sqSum += (x[c] - r[c]) * (x[c] - r[c]);
        }
        if (rel > stats.maxRelMse.value) {
            stats.maxRelMse = {rel, uint32_t(i % width), uint32_t(i / width)};
        }
        ++stats.pixels;
    });
    if (stats.pixels == 0) {
        stats.maxRelMse = {};
        return stats;
    }
    stats.relMse = relSum / double(stats.pixels);
    stats.mse = sqSum / (3.0 * double(stats.pixels));
    stats.rmse = std::sqrt(stats.mse);
    return stats;
}

double relMse(const image::Image& reference, const image::Image& test) {
    return errorStats(reference, test).relMse;
}

double rmse(const image::Image& reference, const image::Image& test) {
    return errorStats(reference, test).rmse;
}

double psnr(const image::Image& reference, const image::Image& test, double peak) {
    const double mse = errorStats(reference, test).mse;
    if (mse == 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    return 10.0 * std::log10(peak * peak / mse);
}

std::vector<float> relMseMap(const image::Image& reference, const image::Image& test) {
    checkPair(reference, test);
    std::vector<float> map(reference.pixelCount(), std::numeric_limits<float>::quiet_NaN());
    forFinitePairs(reference, test,
                   [&](size_t i, const auto& r, const auto& x) { map[i] = float(pixelRelMse(r, x)); });
    return map;
}

} // namespace lumina::measure
