#include "gi/measure/flip.h"

#include "gi/image/display.h"
#include "gi/measure/flip_color.h"
#include "gi/measure/flip_filters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <future>
#include <numbers>
#include <span>

namespace lumina::measure {

namespace {

using flipmath::Color3;

// One image in YyCxCz, as three planes.
struct OpponentPlanes {
    std::array<std::vector<float>, 3> planes;
};

OpponentPlanes toYcxcz(const image::Image& srgb) {
    std::span<const float> r = srgb.channel("R");
    std::span<const float> g = srgb.channel("G");
    std::span<const float> b = srgb.channel("B");
    OpponentPlanes out;
    for (auto& plane : out.planes) {
        plane.resize(srgb.pixelCount());
    }
    for (size_t i = 0; i < srgb.pixelCount(); ++i) {
        const Color3 linear = {image::srgbDecode(r[i]), image::srgbDecode(g[i]), image::srgbDecode(b[i])};
        const Color3 opponent = flipmath::xyzToYcxcz(flipmath::linearRgbToXyz(linear));
        out.planes[0][i] = opponent.x;
        out.planes[1][i] = opponent.y;
        out.planes[2][i] = opponent.z;
    }
    return out;
}

// Colour pipeline up to the difference: CSF-filtered YyCxCz -> linear RGB clamped to [0,1] ->
// L*a*b* -> Hunt adjustment, per pixel.
std::vector<Color3> filteredHuntLab(const OpponentPlanes& input, uint32_t width, uint32_t height,
                                    const std::array<flipmath::CsfFilter, 3>& filters) {
    const size_t count = size_t(width) * height;
    std::array<std::vector<float>, 3> filtered;
    std::vector<float> scratch, term;
    for (size_t c = 0; c < 3; ++c) {
        filtered[c].resize(count);
        flipmath::applyCsf(input.planes[c], filtered[c], width, height, filters[c], scratch, term);
    }
    std::vector<Color3> lab(count);
    for (size_t i = 0; i < count; ++i) {
        Color3 rgb =
            flipmath::xyzToLinearRgb(flipmath::ycxczToXyz({filtered[0][i], filtered[1][i], filtered[2][i]}));
        rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f), std::clamp(rgb.z, 0.0f, 1.0f)};
        lab[i] = flipmath::huntAdjust(flipmath::xyzToLab(flipmath::linearRgbToXyz(rgb)));
    }
    return lab;
}

struct FeatureMagnitudes {
    std::vector<float> edge;
    std::vector<float> point;
};

// Feature pipeline detectors on the achromatic channel of the unfiltered image, normalised to
// [0,1] as (Yy + 16) / 116 (= Y / Y_white).
FeatureMagnitudes detectFeatures(const std::vector<float>& yy, uint32_t width, uint32_t height,
                                 const flipmath::FeatureFilters& filters) {
    const size_t count = size_t(width) * height;
    std::vector<float> gray(count);
    for (size_t i = 0; i < count; ++i) {
        gray[i] = (yy[i] + 16.0f) / 116.0f;
    }
    std::vector<float> scratch, dx(count), dy(count);
    FeatureMagnitudes out{std::vector<float>(count), std::vector<float>(count)};
    flipmath::correlateSeparable(gray, dx, width, height, filters.edge, filters.smooth, scratch);
    flipmath::correlateSeparable(gray, dy, width, height, filters.smooth, filters.edge, scratch);
    for (size_t i = 0; i < count; ++i) {
        out.edge[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
    }
    flipmath::correlateSeparable(gray, dx, width, height, filters.point, filters.smooth, scratch);
    flipmath::correlateSeparable(gray, dy, width, height, filters.smooth, filters.point, scratch);
    for (size_t i = 0; i < count; ++i) {
        out.point[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
    }
    return out;
}

struct Analysis {
    std::vector<Color3> lab;    // CSF-filtered, Hunt-adjusted L*a*b*
    FeatureMagnitudes features; // edge and point magnitudes
};

} // namespace

double pixelsPerDegree(double distance, double monitorWidth, double horizontalPixels) {
    return distance * (horizontalPixels / monitorWidth) * std::numbers::pi / 180.0;
}

FlipResult flip(const image::Image& referenceSrgb, const image::Image& testSrgb, const FlipOptions& options) {
    image::requireSameSize(referenceSrgb, testSrgb, "FLIP");
    if (!referenceSrgb.hasRgb() || !testSrgb.hasRgb()) {
        throw image::ImageError("FLIP: both images need R, G, B channels");
    }
    const uint32_t width = referenceSrgb.width();
    const uint32_t height = referenceSrgb.height();
    const size_t count = referenceSrgb.pixelCount();
    const auto csf = flipmath::makeCsfFilters(options.pixelsPerDegree);
    const auto features = flipmath::makeFeatureFilters(options.pixelsPerDegree);

    // The two images go through the pipelines independently: the reference on a second thread.
    auto analyse = [&](const image::Image& srgb) {
        const OpponentPlanes opponent = toYcxcz(srgb);
        return Analysis{filteredHuntLab(opponent, width, height, csf),
                        detectFeatures(opponent.planes[0], width, height, features)};
    };
    auto referenceTask = std::async(std::launch::async, analyse, std::cref(referenceSrgb));
    const Analysis test = analyse(testSrgb);
    const Analysis reference = referenceTask.get();
    const std::vector<Color3>& referenceLab = reference.lab;
    const std::vector<Color3>& testLab = test.lab;
    const FeatureMagnitudes& referenceFeatures = reference.features;
    const FeatureMagnitudes& testFeatures = test.features;

    FlipResult result;
    result.width = width;
    result.height = height;
    result.errorMap.resize(count);
    if (options.keepComponents) {
        result.colorMap.resize(count);
        result.featureMap.resize(count);
    }
    const float cmax = flipmath::maxColorDistance();
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const float colorErr = flipmath::colorError(flipmath::hyab(referenceLab[i], testLab[i]), cmax);
        const float featureErr = flipmath::featureError(referenceFeatures.edge[i], testFeatures.edge[i],
                                                        referenceFeatures.point[i], testFeatures.point[i]);
        const float error = flipmath::combineErrors(colorErr, featureErr);
        result.errorMap[i] = error;
        if (options.keepComponents) {
            result.colorMap[i] = colorErr;
            result.featureMap[i] = featureErr;
        }
        sum += error;
        if (error > result.max) {
            result.max = error;
            result.maxX = uint32_t(i % width);
            result.maxY = uint32_t(i / width);
        }
    }
    result.mean = sum / double(count);
    return result;
}

} // namespace lumina::measure
