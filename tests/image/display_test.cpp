#include "gi/image/display.h"
#include "shaders/common/tonemap_shared.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::image {
namespace {

// Narkowicz's fit written out: x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14).
double aces(double x) {
    return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
}

TEST(Tonemap, AcesFittedMatchesThePublishedCurve) {
    for (double x : {0.0, 0.01, 0.18, 0.5, 1.0, 2.0, 5.0}) {
        EXPECT_NEAR(gpu::acesFitted(float(x)), std::min(aces(x), 1.0), 1e-6) << x;
    }
    // "1 on input maps to ~0.8 on output" (Narkowicz 2016).
    EXPECT_NEAR(gpu::acesFitted(1.0f), 2.54 / 3.16, 1e-6);
}

TEST(Tonemap, AcesFittedIsMonotonicAndBounded) {
    float previous = -1.0f;
    for (float x = 0.0f; x < 20.0f; x += 0.01f) {
        const float y = gpu::acesFitted(x);
        EXPECT_GE(y, previous) << x;
        EXPECT_LE(y, 1.0f);
        previous = y;
    }
    EXPECT_EQ(gpu::acesFitted(1.0e30f), 1.0f);
    EXPECT_EQ(gpu::acesFitted(std::numeric_limits<float>::infinity()), 1.0f);
    EXPECT_EQ(gpu::acesFitted(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    // Negative radiance must not fold back to a bright value.
    EXPECT_EQ(gpu::acesFitted(-0.2f), 0.0f);
}

TEST(Tonemap, SrgbKnownValues) {
    EXPECT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-6);
    EXPECT_NEAR(srgbEncode(0.0031308f), 0.04045f, 1e-5);
    EXPECT_NEAR(srgbEncode(0.18f), 0.461356f, 1e-5);
    EXPECT_NEAR(srgbEncode(0.5f), 0.735357f, 1e-5);
    EXPECT_NEAR(srgbEncode(0.001f), 0.01292f, 1e-6);
    EXPECT_EQ(srgbEncode(2.0f), 1.0f);
    EXPECT_EQ(srgbEncode(-1.0f), 0.0f);
    for (float v = 0.0f; v <= 1.0f; v += 0.01f) {
        EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 2e-6) << v;
    }
}

TEST(Tonemap, ExposureScalesRadianceByPowersOfTwo) {
    EXPECT_FLOAT_EQ(toDisplay(0.25f, {.exposureEv = 1.0f}), toDisplay(0.5f));
    EXPECT_FLOAT_EQ(toDisplay(0.5f, {.exposureEv = -2.0f}), toDisplay(0.125f));
    EXPECT_FLOAT_EQ(toDisplay(0.18f, {.tonemap = Tonemap::Clamp}), srgbEncode(0.18f));
    EXPECT_FLOAT_EQ(toDisplay(0.18f), srgbEncode(float(aces(0.18))));
}

TEST(Tonemap, ImageTransformKeepsRgbOnly) {
    Image linear = Image::rgba(2, 1);
    linear.addChannel("variance", 5.0f);
    linear.setRgb(0, 0, {0.18f, 1.0f, 100.0f});
    linear.setRgb(1, 0,
                  {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -1.0f});
    const Image display = toDisplay(linear);
    EXPECT_EQ(display.channelNames(), (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_FLOAT_EQ(display.at("R", 0, 0), toDisplay(0.18f));
    EXPECT_FLOAT_EQ(display.at("B", 0, 0), 1.0f);
    EXPECT_EQ(display.at("R", 1, 0), 0.0f);
    EXPECT_EQ(display.at("G", 1, 0), 1.0f);
    EXPECT_EQ(display.at("B", 1, 0), 0.0f);
    EXPECT_THROW(toDisplay(Image(1, 1, {"Y"})), ImageError);
}

} // namespace
} // namespace lumina::image
