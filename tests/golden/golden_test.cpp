// The golden compare itself: its statistics, the evidence a failure leaves, and the guard on
// regeneration (only Debian 12's lavapipe may write goldens).
#include "tests/golden/golden.h"
#include "tests/image/temp_dir.h"
#include "tests/test_env.h"

#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <limits>

namespace lumina::test {
namespace {

constexpr uint32_t kSide = 10; // 100 pixels: the 99th percentile ignores exactly one

image::Image ramp() {
    image::Image image = image::Image::rgb(kSide, kSide);
    for (uint32_t y = 0; y < kSide; ++y) {
        for (uint32_t x = 0; x < kSide; ++x) {
            image.setRgb(x, y, {float(x) / kSide, float(y) / kSide, 0.5f});
        }
    }
    return image;
}

rhi::AdapterInfo adapter(const char* name, const char* driver) {
    rhi::AdapterInfo info;
    info.name = name;
    info.driver = driver;
    return info;
}

rhi::AdapterInfo lavapipe() {
    return adapter("llvmpipe (LLVM 15.0.6, 256 bits)", "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)");
}

TEST(GoldenCompare, IdenticalImagesHaveNoError) {
    const GoldenStats stats = compareWithGolden(ramp(), ramp(), 0.99);
    EXPECT_EQ(stats.meanAbsError, 0.0);
    EXPECT_EQ(stats.percentileError, 0.0);
    EXPECT_EQ(stats.maxError, 0.0);
}

TEST(GoldenCompare, PercentileIgnoresTheWorstOnePercent) {
    image::Image actual = ramp();
    actual.set("G", 3, 4, actual.at("G", 3, 4) + 0.5f);
    GoldenStats stats = compareWithGolden(ramp(), actual, 0.99);
    EXPECT_EQ(stats.percentileError, 0.0f);
    EXPECT_NEAR(stats.maxError, 0.5, 1e-6);
    EXPECT_NEAR(stats.meanAbsError, 0.5 / (kSide * kSide * 3), 1e-9);
    EXPECT_NEAR(stats.pixelErrors[4 * kSide + 3], 0.5f, 1e-6f);

    actual.set("R", 7, 7, actual.at("R", 7, 7) - 0.25f);
    stats = compareWithGolden(ramp(), actual, 0.99);
    EXPECT_NEAR(stats.percentileError, 0.25, 1e-6);
}

TEST(GoldenCompare, NanIsAnInfiniteError) {
    image::Image actual = ramp();
    actual.set("B", 0, 0, std::numeric_limits<float>::quiet_NaN());
    const GoldenStats stats = compareWithGolden(ramp(), actual, 0.99);
    EXPECT_TRUE(std::isinf(stats.maxError));
    EXPECT_TRUE(std::isinf(stats.meanAbsError));
}

TEST(GoldenCompare, MissingChannelOrSizeIsAnError) {
    image::Image withAlpha = ramp();
    withAlpha.addChannel("A", 1.0f);
    EXPECT_THROW(compareWithGolden(withAlpha, ramp(), 0.99), image::ImageError);
    EXPECT_THROW(compareWithGolden(ramp(), image::Image::rgb(kSide + 1, kSide), 0.99), image::ImageError);
}

TEST(GoldenUpdate, OnlyDebianLavapipeMayWriteGoldens) {
    std::string why;
    EXPECT_TRUE(goldenUpdateAllowed(lavapipe(), why));
    rhi::AdapterInfo newerMesa = lavapipe();
    newerMesa.driver = "llvmpipe Mesa 24.0.5 (LLVM 17.0.6)";
    EXPECT_FALSE(goldenUpdateAllowed(newerMesa, why));
    EXPECT_NE(why.find("Mesa 24.0.5"), std::string::npos) << why;
    EXPECT_FALSE(goldenUpdateAllowed(adapter("NVIDIA GeForce RTX 4090", "NVIDIA 550.54"), why));
}

class GoldenFiles : public lumina::testing::TempDir {
protected:
    void SetUp() override {
        TempDir::SetUp();
        previous_ = std::filesystem::current_path();
        std::filesystem::current_path(path(""));
        lumina::testing::setEnv("LUMINA_SOURCE_DIR", path("source").string());
    }
    void TearDown() override {
        lumina::testing::unsetEnv("LUMINA_UPDATE_GOLDENS");
        std::filesystem::current_path(previous_);
        TempDir::TearDown();
    }
    std::filesystem::path previous_;
};

TEST_F(GoldenFiles, UpdateWritesTheGoldenThenItPasses) {
    lumina::testing::setEnv("LUMINA_UPDATE_GOLDENS", "1");
    GoldenResult result = checkGolden({.name = "ramp"}, ramp(), lavapipe());
    ASSERT_TRUE(result.passed) << result.message;
    EXPECT_TRUE(result.updated);
    EXPECT_TRUE(std::filesystem::exists(path("source/tests/golden/data/ramp.exr")));
    EXPECT_TRUE(std::filesystem::exists(path("source/tests/golden/data/ramp.png")));
    lumina::testing::unsetEnv("LUMINA_UPDATE_GOLDENS");
    result = checkGolden({.name = "ramp"}, ramp(), lavapipe());
    EXPECT_TRUE(result.passed) << result.message;
    EXPECT_FALSE(result.updated);
}

TEST_F(GoldenFiles, UpdateIsRefusedOnAnotherDriver) {
    lumina::testing::setEnv("LUMINA_UPDATE_GOLDENS", "1");
    const GoldenResult result =
        checkGolden({.name = "ramp"}, ramp(), adapter("llvmpipe", "llvmpipe Mesa 23.1.0"));
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.message.find("refused"), std::string::npos) << result.message;
    EXPECT_FALSE(std::filesystem::exists(path("source/tests/golden/data/ramp.exr")));
}

TEST_F(GoldenFiles, FailureWritesActualExpectedAndDiff) {
    lumina::testing::setEnv("LUMINA_UPDATE_GOLDENS", "1");
    ASSERT_TRUE(checkGolden({.name = "ramp"}, ramp(), lavapipe()).passed);
    lumina::testing::unsetEnv("LUMINA_UPDATE_GOLDENS");

    image::Image actual = ramp();
    for (uint32_t x = 0; x < kSide; ++x) { // a whole row off: beyond the percentile
        actual.set("R", x, 2, 1.0f);
    }
    const GoldenResult result = checkGolden({.name = "ramp"}, actual, lavapipe());
    EXPECT_FALSE(result.passed);
    for (const char* file : {"ramp_actual.exr", "ramp_actual.png", "ramp_expected.png", "ramp_diff.png"}) {
        const std::filesystem::path written = path("golden_failures") / file;
        EXPECT_TRUE(std::filesystem::exists(written)) << written;
        EXPECT_NE(result.message.find(file), std::string::npos) << result.message;
    }
}

TEST_F(GoldenFiles, MissingGoldenFailsAndSaysHowToMakeIt) {
    const GoldenResult result = checkGolden({.name = "absent"}, ramp(), lavapipe());
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.message.find("LUMINA_UPDATE_GOLDENS=1"), std::string::npos) << result.message;
    EXPECT_TRUE(std::filesystem::exists(path("golden_failures/absent_actual.exr")));
}

} // namespace
} // namespace lumina::test
