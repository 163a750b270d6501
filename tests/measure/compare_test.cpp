#include "gi/measure/compare.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>

namespace lumina::measure {
namespace {

using image::Image;

Image hdr(uint32_t w, uint32_t h, float scale) {
    Image image = Image::rgb(w, h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            image.setRgb(x, y, {scale * float(x) / float(w), scale * float(y) / float(h), scale * 4.0f});
        }
    }
    return image;
}

TEST(Compare, IdenticalImages) {
    const Image image = hdr(16, 8, 3.0f);
    const CompareResult result = compareImages(image, image);
    EXPECT_EQ(result.width, 16u);
    EXPECT_EQ(result.height, 8u);
    EXPECT_EQ(result.linear.relMse, 0.0);
    EXPECT_EQ(result.linear.rmse, 0.0);
    EXPECT_TRUE(std::isinf(result.psnr));
    EXPECT_EQ(result.flip.mean, 0.0);
    EXPECT_FALSE(result.hasNonFinite());
    const auto json = nlohmann::json::parse(compareReportJson(result, "a.exr", "a.exr", {}));
    EXPECT_TRUE(json["psnr_db"].is_null());
    EXPECT_EQ(json["ok"], true);
}

TEST(Compare, CombinesLinearAndDisplayMetrics) {
    const Image reference = hdr(24, 16, 2.0f);
    const Image test = hdr(24, 16, 2.2f);
    CompareOptions options;
    options.display.exposureEv = -1.0f;
    const CompareResult result = compareImages(reference, test, options);
    const ErrorStats stats = errorStats(reference, test);
    EXPECT_DOUBLE_EQ(result.linear.relMse, stats.relMse);
    EXPECT_DOUBLE_EQ(result.linear.rmse, stats.rmse);
    // PSNR is taken on the display images (same exposure for both), peak 1.
    const double displayPsnr =
        psnr(image::toDisplay(reference, options.display), image::toDisplay(test, options.display), 1.0);
    EXPECT_NEAR(result.psnr, displayPsnr, 1e-6);
    const FlipResult direct =
        flip(image::toDisplay(reference, options.display), image::toDisplay(test, options.display));
    EXPECT_DOUBLE_EQ(result.flip.mean, direct.mean);
    EXPECT_GT(result.flip.mean, 0.0);
    EXPECT_EQ(result.flip.errorMap.size(), 24u * 16u);

    const auto json = nlohmann::json::parse(compareReportJson(result, "ref.exr", "test.exr", options));
    EXPECT_EQ(json["reference"], "ref.exr");
    EXPECT_EQ(json["test"], "test.exr");
    EXPECT_EQ(json["width"], 24);
    EXPECT_DOUBLE_EQ(json["relmse"].get<double>(), stats.relMse);
    EXPECT_DOUBLE_EQ(json["flip"]["mean"].get<double>(), direct.mean);
    EXPECT_EQ(json["max_error"]["metric"], "relmse");
    EXPECT_EQ(json["display"]["exposure_ev"], -1.0);
    EXPECT_EQ(json["nonfinite"]["test"]["nan_pixels"], 0);
}

TEST(Compare, NonFinitePixelsAreReportedNotThrown) {
    const Image reference = hdr(8, 8, 1.0f);
    Image test = reference;
    test.set("R", 2, 3, std::numeric_limits<float>::quiet_NaN());
    test.set("B", 4, 4, std::numeric_limits<float>::infinity());
    const CompareResult result = compareImages(reference, test);
    EXPECT_TRUE(result.hasNonFinite());
    EXPECT_EQ(result.test.nanPixels, 1u);
    EXPECT_EQ(result.test.infPixels, 1u);
    EXPECT_EQ(result.reference.total(), 0u);
    EXPECT_EQ(result.linear.pixels, 62u);
    EXPECT_EQ(result.linear.relMse, 0.0); // the other 62 pixels agree
    EXPECT_TRUE(std::isfinite(result.flip.mean));
    const auto json = nlohmann::json::parse(compareReportJson(result, "r", "t", {}));
    EXPECT_EQ(json["ok"], false);
    EXPECT_EQ(json["nonfinite"]["test"]["nan_pixels"], 1);
    EXPECT_EQ(json["nonfinite"]["test"]["inf_pixels"], 1);
}

TEST(Compare, SizeMismatchThrows) {
    EXPECT_THROW(compareImages(hdr(8, 8, 1.0f), hdr(8, 9, 1.0f)), image::ImageError);
}

} // namespace
} // namespace lumina::measure
