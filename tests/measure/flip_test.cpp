#include "gi/measure/flip.h"
#include "gi/measure/flip_color.h"
#include "gi/measure/flip_filters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <numeric>
#include <random>

namespace lumina::measure {
namespace {

using image::Image;
using Srgb = std::array<double, 3>;

Image uniform(uint32_t w, uint32_t h, Srgb c) {
    Image image = Image::rgb(w, h);
    image.fillRgb({float(c[0]), float(c[1]), float(c[2])});
    return image;
}

double mean(const std::vector<float>& values) {
    return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

// ---- FLIP of two flat colours, written out from the paper's formulas in double precision.
// On flat images the CSF filters (normalised to 1) leave colours unchanged and both feature
// detectors (lobes summing to +1 and -1) answer 0, so Delta E = Delta E_c.
double srgbToLinear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

std::array<double, 3> huntLab(Srgb srgb) {
    const double m[3][3] = {{0.4123908, 0.3575843, 0.1804808},
                            {0.2126390, 0.7151687, 0.0721923},
                            {0.0193308, 0.1191948, 0.9505322}};
    double xyz[3];
    double white[3];
    for (int i = 0; i < 3; ++i) {
        xyz[i] = 0.0;
        white[i] = 0.0;
        for (int j = 0; j < 3; ++j) {
            xyz[i] += m[i][j] * srgbToLinear(srgb[size_t(j)]);
            white[i] += m[i][j];
        }
    }
    auto f = [](double t) {
        const double d = 6.0 / 29.0;
        return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    const double L = 116 * fy - 16, a = 500 * (fx - fy), b = 200 * (fy - fz);
    return {L, 0.01 * L * a, 0.01 * L * b}; // Hunt: chroma scaled by L/100
}

double hyab(const std::array<double, 3>& p, const std::array<double, 3>& q) {
    return std::fabs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

double handFlatFlip(Srgb reference, Srgb test) {
    const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), 0.7);
    const double e = std::pow(hyab(huntLab(reference), huntLab(test)), 0.7);
    const double pc = 0.4 * cmax;
    return e < pc ? e * 0.95 / pc : 0.95 + (e - pc) / (cmax - pc) * 0.05;
}

// ---- tests

TEST(Flip, DefaultObserverIs67PixelsPerDegree) {
    EXPECT_NEAR(pixelsPerDegree(0.7, 0.7, 3840.0), 67.0206, 1e-4);
    EXPECT_NEAR(kDefaultPixelsPerDegree, pixelsPerDegree(0.7, 0.7, 3840.0), 1e-9);
}

TEST(FlipFilters, CsfKernelsAreNormalised) {
    EXPECT_EQ(flipmath::csfRadius(kDefaultPixelsPerDegree), 10); // ceil(3 sqrt(0.04 / 2pi^2) 67.02)
    const auto filters = flipmath::makeCsfFilters(kDefaultPixelsPerDegree);
    EXPECT_EQ(filters[0].terms.size(), 1u); // achromatic: a2 = 0
    EXPECT_EQ(filters[1].terms.size(), 1u); // red-green: a2 = 0
    EXPECT_EQ(filters[2].terms.size(), 2u); // blue-yellow: two Gaussians
    for (const auto& filter : filters) {
        double weights = 0.0;
        for (const auto& term : filter.terms) {
            weights += term.weight;
            EXPECT_NEAR(std::accumulate(term.kernel.taps.begin(), term.kernel.taps.end(), 0.0), 1.0, 1e-6);
            EXPECT_EQ(term.kernel.taps.size(), 21u);
        }
        EXPECT_NEAR(weights, 1.0, 1e-6);
    }
    // The blue-yellow filter is much wider than the achromatic one (lower acuity for chroma).
    EXPECT_LT(filters[2].terms[0].kernel.taps[10], filters[0].terms[0].kernel.taps[10]);
}

TEST(FlipFilters, FeatureDetectorLobesSumToPlusMinusOne) {
    const auto filters = flipmath::makeFeatureFilters(kDefaultPixelsPerDegree);
    EXPECT_NEAR(filters.sigma, 0.5 * 0.082 * kDefaultPixelsPerDegree, 1e-5);
    EXPECT_EQ(filters.radius, 9);
    for (const auto* kernel : {&filters.edge, &filters.point}) {
        double positive = 0.0, negative = 0.0;
        for (float t : kernel->taps) {
            (t > 0 ? positive : negative) += t;
        }
        EXPECT_NEAR(positive, 1.0, 1e-6);
        EXPECT_NEAR(negative, -1.0, 1e-6);
    }
    EXPECT_NEAR(std::accumulate(filters.smooth.taps.begin(), filters.smooth.taps.end(), 0.0), 1.0, 1e-6);
    // Edge: odd, negative for positive offsets (-x G). Point: negative centre.
    EXPECT_LT(filters.edge.taps[10], 0.0f);
    EXPECT_FLOAT_EQ(filters.edge.taps[8], -filters.edge.taps[10]);
    EXPECT_LT(filters.point.taps[9], 0.0f);
}

// Chromatic detail is filtered harder than achromatic detail (the CSFs' widths): a 1-pixel
// checkerboard in each opponent channel, at 20 ppd, keeps far less amplitude in blue-yellow.
TEST(FlipFilters, ChromaticChannelsBlurMoreThanAchromatic) {
    const uint32_t n = 32;
    std::vector<float> pattern(n * n), out(n * n), scratch, term;
    for (uint32_t i = 0; i < n * n; ++i) {
        pattern[i] = ((i % n) + (i / n)) % 2 == 0 ? 1.0f : -1.0f;
    }
    const auto filters = flipmath::makeCsfFilters(20.0);
    std::array<float, 3> amplitude{};
    for (size_t c = 0; c < 3; ++c) {
        flipmath::applyCsf(pattern, out, n, n, filters[c], scratch, term);
        amplitude[c] = std::fabs(out[16 * n + 16]); // centre, away from borders
    }
    EXPECT_GT(amplitude[0], 0.1f);                 // achromatic: partly resolved at 20 ppd
    EXPECT_LT(amplitude[1], amplitude[0]);         // red-green: slightly wider (b 0.0053 vs 0.0047)
    EXPECT_LT(amplitude[2], 0.01f * amplitude[0]); // blue-yellow: gone
    // A flat field passes unchanged through every filter.
    std::vector<float> flat(n * n, 0.25f);
    for (size_t c = 0; c < 3; ++c) {
        flipmath::applyCsf(flat, out, n, n, filters[c], scratch, term);
        EXPECT_NEAR(out[0], 0.25f, 1e-6f);
        EXPECT_NEAR(out[16 * n + 16], 0.25f, 1e-6f);
    }
}

TEST(Flip, IdenticalImagesGiveZero) {
    Image image = Image::rgb(24, 16);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const char* c : {"R", "G", "B"}) {
        for (float& v : image.channel(c)) {
            v = unit(random);
        }
    }
    const FlipResult result = flip(image, image);
    EXPECT_EQ(result.mean, 0.0);
    EXPECT_EQ(result.max, 0.0f);
    ASSERT_EQ(result.errorMap.size(), 24u * 16u);
    EXPECT_TRUE(
        std::all_of(result.errorMap.begin(), result.errorMap.end(), [](float v) { return v == 0.0f; }));
}

TEST(Flip, ValuesStayInZeroOne) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> wide(-0.5f, 1.5f); // out-of-range input is clamped
    Image a = Image::rgb(32, 20);
    Image b = Image::rgb(32, 20);
    for (Image* image : {&a, &b}) {
        for (const char* c : {"R", "G", "B"}) {
            for (float& v : image->channel(c)) {
                v = wide(random);
            }
        }
    }
    for (double ppd : {1.0, 10.0, kDefaultPixelsPerDegree, 200.0}) {
        const FlipResult result = flip(a, b, {.pixelsPerDegree = ppd});
        for (float v : result.errorMap) {
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
        }
        EXPECT_GT(result.mean, 0.0);
        EXPECT_LE(result.mean, 1.0);
        EXPECT_EQ(result.errorMap[result.maxY * 32 + result.maxX], result.max);
    }
    // Extreme: black against white, and a checkerboard of them against its inverse.
    const FlipResult extreme = flip(uniform(8, 8, {0, 0, 0}), uniform(8, 8, {1, 1, 1}));
    EXPECT_LE(extreme.max, 1.0f);
}

TEST(Flip, SymmetricInItsArguments) {
    Image a = uniform(16, 16, {0.2, 0.4, 0.6});
    Image b = uniform(16, 16, {0.2, 0.4, 0.6});
    b.setRgb(5, 7, {0.9f, 0.1f, 0.1f});
    EXPECT_DOUBLE_EQ(flip(a, b).mean, flip(b, a).mean);
}

TEST(Flip, FlatImagesMatchTheHandComputedColourTerm) {
    const std::array<std::pair<Srgb, Srgb>, 5> pairs = {{
        {{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}},
        {{0.2, 0.4, 0.6}, {0.25, 0.35, 0.6}},
        {{0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},
        {{0.0, 0.0, 0.0}, {0.02, 0.01, 0.0}},
        {{0.3, 0.3, 0.1}, {0.3, 0.3, 0.9}},
    }};
    for (const auto& [ref, test] : pairs) {
        const FlipResult result = flip(uniform(12, 10, ref), uniform(12, 10, test), {.keepComponents = true});
        const double expected = handFlatFlip(ref, test);
        EXPECT_NEAR(result.mean, expected, 2e-4) << ref[0] << "," << ref[1] << "," << ref[2];
        EXPECT_NEAR(result.max, expected, 2e-4);
        for (float f : result.featureMap) {
            ASSERT_NEAR(f, 0.0f, 2e-3); // features vanish on flat images (up to float rounding)
        }
    }
    // A literal anchor: black vs white. L* 0 vs 100, HyAB = 100; c_max = 203.305^0.7 = 41.2766;
    // 100^0.7 = 25.1189 >= 0.4 c_max, so 0.95 + (25.1189 - 16.5106) / (41.2766 - 16.5106) * 0.05.
    EXPECT_NEAR(flip(uniform(4, 4, {0, 0, 0}), uniform(4, 4, {1, 1, 1})).mean, 0.967379, 1e-4);
    EXPECT_NEAR(handFlatFlip({0, 0, 0}, {1, 1, 1}), 0.967379, 1e-5);
    // Grey 0.5 vs 0.6 sRGB: L* 53.389 vs 63.223, below the knee: 9.8336^0.7 * 0.95 / (0.4 c_max).
    EXPECT_NEAR(handFlatFlip({0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}), 0.285010, 1e-5);
}

TEST(Flip, LargerColourDifferenceGivesLargerError) {
    const Srgb base = {0.4, 0.4, 0.4};
    double previous = 0.0;
    for (double step : {0.01, 0.03, 0.1, 0.3, 0.6}) {
        const double value = flip(uniform(8, 8, base), uniform(8, 8, {0.4 + step, 0.4, 0.4})).mean;
        EXPECT_GT(value, previous) << step;
        previous = value;
    }
    previous = 0.0;
    for (double step : {0.02, 0.1, 0.3}) {
        const double value = flip(uniform(8, 8, base), uniform(8, 8, {0.4 - step, 0.4 + step, 0.4})).mean;
        EXPECT_GT(value, previous) << step;
        previous = value;
    }
}

// HyAB measures lightness city-block and chroma Euclidean, after the Hunt adjustment scales
// chroma by L*/100: a pure lightness difference counts in full at any
// level, while the same chromatic difference fades as the colours darken.
TEST(Flip, LuminanceAndHueDifferencesFollowTheHuntAdjustedHyAB) {
    // Pure lightness: the error is exactly the compressed |Delta L*|.
    const Srgb gray1 = {0.3, 0.3, 0.3}, gray2 = {0.4, 0.4, 0.4};
    const auto l1 = huntLab(gray1), l2 = huntLab(gray2);
    EXPECT_NEAR(hyab(l1, l2), std::fabs(l1[0] - l2[0]), 1e-9);
    const float cmax = flipmath::maxColorDistance();
    EXPECT_NEAR(flip(uniform(8, 8, gray1), uniform(8, 8, gray2)).mean,
                flipmath::colorError(float(std::fabs(l1[0] - l2[0])), cmax), 2e-4);

    // Hue: swap red and green at the same lightness level, bright and dark. The dark pair
    // differs in a*, b* by about as much in plain CIELab but far less after the Hunt adjustment.
    const Srgb brightRed = {0.8, 0.4, 0.4}, brightGreen = {0.4, 0.8, 0.4};
    const Srgb darkRed = {0.2, 0.1, 0.1}, darkGreen = {0.1, 0.2, 0.1};
    const double bright = flip(uniform(8, 8, brightRed), uniform(8, 8, brightGreen)).mean;
    const double dark = flip(uniform(8, 8, darkRed), uniform(8, 8, darkGreen)).mean;
    EXPECT_GT(bright, dark);

    // Hunt: an a* difference at L* = 20 weighs a fifth of the same at L* = 100.
    const flipmath::Color3 low = flipmath::huntAdjust({20.0f, 30.0f, 0.0f});
    const flipmath::Color3 high = flipmath::huntAdjust({100.0f, 30.0f, 0.0f});
    EXPECT_NEAR(low.y * 5.0f, high.y, 1e-4f);
    // HyAB: a lightness and a chroma difference add (city block), chroma components do not.
    EXPECT_NEAR(flipmath::hyab({50, 0, 0}, {53, 4, 0}), 7.0f, 1e-5f);
    EXPECT_NEAR(flipmath::hyab({50, 0, 0}, {50, 3, 4}), 5.0f, 1e-5f);
}

Image checkerboard(uint32_t size, Srgb a, Srgb b) {
    Image image = Image::rgb(size, size);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const Srgb& c = (x + y) % 2 == 0 ? a : b;
            image.setRgb(x, y, {float(c[0]), float(c[1]), float(c[2])});
        }
    }
    return image;
}

// The CSF removes detail the eye cannot resolve: a 1-pixel checkerboard of two close colours
// against their mean is less visible than the same difference spread over flat regions, and
// it becomes visible again when the observer's pixels are large (low ppd).
TEST(Flip, ContrastSensitivityHidesFinePatterns) {
    const uint32_t n = 32;
    const Srgb mid = {0.5, 0.5, 0.5}, lighter = {0.56, 0.56, 0.56}, darker = {0.44, 0.44, 0.44};
    const Image reference = uniform(n, n, mid);
    const Image fine = checkerboard(n, lighter, darker);
    const Image flat = uniform(n, n, lighter);

    const FlipResult fineResult = flip(reference, fine, {.keepComponents = true});
    const FlipResult flatResult = flip(reference, flat, {.keepComponents = true});
    EXPECT_LT(mean(fineResult.colorMap), 0.2 * mean(flatResult.colorMap));
    EXPECT_LT(fineResult.mean, flatResult.mean);

    const FlipResult coarseViewer = flip(reference, fine, {.pixelsPerDegree = 8.0, .keepComponents = true});
    EXPECT_GT(mean(coarseViewer.colorMap), 3.0 * mean(fineResult.colorMap));
    EXPECT_GT(coarseViewer.mean, fineResult.mean);
}

// A point or an edge the CSF softens still registers through the feature pipeline: the
// combined error exceeds the colour term where the feature is.
TEST(Flip, FeaturesRaiseTheErrorBeyondTheColourTerm) {
    const uint32_t n = 33;
    const Image reference = uniform(n, n, {0.5, 0.5, 0.5});

    Image point = reference;
    point.setRgb(16, 16, {0.7f, 0.7f, 0.7f});
    const FlipResult pointResult = flip(reference, point, {.keepComponents = true});
    const size_t centre = 16 * n + 16;
    EXPECT_GT(pointResult.featureMap[centre], 0.05f);
    EXPECT_GT(pointResult.errorMap[centre], pointResult.colorMap[centre] + 0.01f);
    EXPECT_GT(pointResult.mean, mean(pointResult.colorMap));
    EXPECT_EQ(pointResult.maxX, 16u);
    EXPECT_EQ(pointResult.maxY, 16u);
    // Far from the point nothing changed.
    EXPECT_EQ(pointResult.errorMap[0], 0.0f);

    Image edge = reference;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 17; x < n; ++x) {
            edge.setRgb(x, y, {0.55f, 0.55f, 0.55f});
        }
    }
    const FlipResult edgeResult = flip(reference, edge, {.keepComponents = true});
    const size_t onEdge = 16 * n + 17;
    EXPECT_GT(edgeResult.featureMap[onEdge], 0.05f);
    EXPECT_GT(edgeResult.errorMap[onEdge], edgeResult.colorMap[onEdge]);
    // Away from the edge, on the flat brighter side, the feature term is (nearly) 0.
    EXPECT_LT(edgeResult.featureMap[16 * n + 32], 0.01f);
}

TEST(Flip, RejectsBadInput) {
    EXPECT_THROW(flip(Image::rgb(4, 4), Image::rgb(4, 5)), image::ImageError);
    EXPECT_THROW(flip(Image::rgb(4, 4), Image(4, 4, {"Y"})), image::ImageError);
    EXPECT_THROW(flip(Image::rgb(4, 4), Image::rgb(4, 4), {.pixelsPerDegree = 0.0}), image::ImageError);
    EXPECT_THROW(flip(Image::rgb(4, 4), Image::rgb(4, 4), {.pixelsPerDegree = NAN}), image::ImageError);
    // NaN in the inputs reads as 0 and never propagates.
    Image nan = Image::rgb(4, 4);
    nan.set("R", 1, 1, NAN);
    const FlipResult result = flip(Image::rgb(4, 4), nan);
    EXPECT_TRUE(std::isfinite(result.mean));
}

TEST(Flip, OnePixelImagesWork) {
    const FlipResult result = flip(uniform(1, 1, {0.1, 0.2, 0.3}), uniform(1, 1, {0.3, 0.2, 0.1}));
    EXPECT_GT(result.mean, 0.0);
    EXPECT_NEAR(result.mean, handFlatFlip({0.1, 0.2, 0.3}, {0.3, 0.2, 0.1}), 2e-4);
}

} // namespace
} // namespace lumina::measure
