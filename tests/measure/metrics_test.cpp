#include "gi/measure/metrics.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::measure {
namespace {

using image::Image;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// 2x2 reference and test images with R = G = B per pixel (so per-pixel values are easy):
//   reference 1, 0, 2, 0.1    test 1.5, 0.1, 2, 0.05
Image gray2x2(float a, float b, float c, float d) {
    Image image = Image::rgb(2, 2);
    image.fillRgb({0, 0, 0});
    const float values[] = {a, b, c, d};
    for (uint32_t i = 0; i < 4; ++i) {
        image.setRgb(i % 2, i / 2, {values[i], values[i], values[i]});
    }
    return image;
}

TEST(Metrics, HandComputed2x2) {
    const Image reference = gray2x2(1.0f, 0.0f, 2.0f, 0.1f);
    const Image test = gray2x2(1.5f, 0.1f, 2.0f, 0.05f);
    // Per pixel (x - r)^2 / (r^2 + 0.01):
    //   0.25 / 1.01,   0.01 / 0.01 = 1,   0,   0.0025 / 0.02 = 0.125
    const double rel0 = 0.25 / 1.01;
    const double relMseExpected = (rel0 + 1.0 + 0.0 + 0.125) / 4.0;
    // MSE = (0.25 + 0.01 + 0 + 0.0025) / 4 (R = G = B, so the mean over channels is the same)
    const double mseExpected = (0.25 + 0.01 + 0.0 + 0.0025) / 4.0;
    const ErrorStats stats = errorStats(reference, test);
    EXPECT_EQ(stats.pixels, 4u);
    EXPECT_NEAR(stats.relMse, relMseExpected, 1e-6);
    EXPECT_NEAR(stats.mse, mseExpected, 1e-7);
    EXPECT_NEAR(stats.rmse, std::sqrt(mseExpected), 1e-7);
    EXPECT_NEAR(relMse(reference, test), relMseExpected, 1e-6);
    EXPECT_NEAR(rmse(reference, test), std::sqrt(mseExpected), 1e-7);
    // Largest per-pixel relMSE: pixel (1, 0), value 1.
    EXPECT_NEAR(stats.maxRelMse.value, 1.0, 1e-5);
    EXPECT_EQ(stats.maxRelMse.x, 1u);
    EXPECT_EQ(stats.maxRelMse.y, 0u);
    // PSNR with peak 1: 10 log10(1 / MSE); with peak 2: + 20 log10(2).
    EXPECT_NEAR(psnr(reference, test), 10.0 * std::log10(1.0 / mseExpected), 1e-5);
    EXPECT_NEAR(psnr(reference, test, 2.0), 10.0 * std::log10(4.0 / mseExpected), 1e-5);

    const auto map = relMseMap(reference, test);
    ASSERT_EQ(map.size(), 4u);
    EXPECT_NEAR(map[0], rel0, 1e-6);
    EXPECT_NEAR(map[1], 1.0, 1e-5);
    EXPECT_EQ(map[2], 0.0f);
    EXPECT_NEAR(map[3], 0.125, 1e-6);
}

TEST(Metrics, ChannelsAreAveraged) {
    Image reference = Image::rgb(1, 1);
    Image test = Image::rgb(1, 1);
    reference.setRgb(0, 0, {1.0f, 0.0f, 0.0f});
    test.setRgb(0, 0, {1.0f, 0.3f, 0.0f});
    // Only G differs: relMSE = (0.09 / 0.01) / 3, MSE = 0.09 / 3.
    EXPECT_NEAR(relMse(reference, test), 3.0, 1e-5);
    EXPECT_NEAR(rmse(reference, test), std::sqrt(0.03), 1e-6);
}

TEST(Metrics, IdenticalImagesHaveZeroError) {
    Image image = gray2x2(0.0f, 0.5f, 3.0f, 100.0f);
    EXPECT_EQ(relMse(image, image), 0.0);
    EXPECT_EQ(rmse(image, image), 0.0);
    EXPECT_EQ(psnr(image, image), std::numeric_limits<double>::infinity());
}

TEST(Metrics, NonFinitePixelsAreCountedAndLeftOut) {
    Image reference = gray2x2(1.0f, 1.0f, 1.0f, 1.0f);
    Image test = gray2x2(1.0f, 2.0f, 1.0f, 1.0f);
    test.set("G", 0, 0, kNaN);
    test.set("B", 0, 1, kInf);
    test.set("R", 0, 1, kNaN); // NaN and Inf in one pixel: counted once, as NaN
    reference.set("R", 1, 1, -kInf);
    const NonFiniteCounts testCounts = countNonFinite(test);
    EXPECT_EQ(testCounts.nanPixels, 2u);
    EXPECT_EQ(testCounts.infPixels, 0u);
    const NonFiniteCounts referenceCounts = countNonFinite(reference);
    EXPECT_EQ(referenceCounts.nanPixels, 0u);
    EXPECT_EQ(referenceCounts.infPixels, 1u);
    EXPECT_EQ(referenceCounts.total(), 1u);

    // Only pixel (1, 0) is finite in both: relMSE = 1 / 1.01, RMSE = 1.
    const ErrorStats stats = errorStats(reference, test);
    EXPECT_EQ(stats.pixels, 1u);
    EXPECT_NEAR(stats.relMse, 1.0 / 1.01, 1e-6);
    EXPECT_NEAR(stats.rmse, 1.0, 1e-7);
    EXPECT_TRUE(std::isfinite(stats.relMse));
    const auto map = relMseMap(reference, test);
    EXPECT_TRUE(std::isnan(map[0]));
    EXPECT_FALSE(std::isnan(map[1]));
    EXPECT_TRUE(std::isnan(map[3]));

    Image allInf = gray2x2(kInf, kInf, kInf, kInf);
    EXPECT_EQ(countNonFinite(allInf).infPixels, 4u);
    EXPECT_EQ(errorStats(allInf, allInf).pixels, 0u);
    EXPECT_EQ(errorStats(allInf, allInf).relMse, 0.0);
}

TEST(Metrics, SizeMismatchAndMissingChannelsThrow) {
    const Image a = Image::rgb(2, 2);
    const Image b = Image::rgb(3, 2);
    EXPECT_THROW(relMse(a, b), image::ImageError);
    EXPECT_THROW(psnr(a, b), image::ImageError);
    EXPECT_THROW(relMseMap(a, b), image::ImageError);
    const Image gray(2, 2, {"Y"});
    EXPECT_THROW(rmse(a, gray), image::ImageError);
    EXPECT_THROW(countNonFinite(gray), image::ImageError);
}

} // namespace
} // namespace lumina::measure
