// Every furnace scene (a closed box whose surfaces all have albedo rho and emit Le) has the
// exact radiance Le / (1 - rho) everywhere: the image mean must match it within a few of its
// measured standard errors; the pixels must spread around it as their variance channel says.
#include "tests/pathtracer/path_tracer_fixture.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace lumina::test {
namespace {

using FurnaceTest = PathTracerTest;

// |mean - exact| within this many standard errors (a false failure about once in 16000 runs
// per channel for a normal error).
constexpr double kSigmas = 4.0;
// Pixels farther than kSigmas pooled standard errors from the answer: a few at most (the
// path-length distribution is skewed, so short runs have heavier tails than a normal's).
constexpr double kMaxOutlierFraction = 0.01;
// Sum of squared pixel errors over the sum of reported variances: 1 on average, within about
// +-15% (3 sigma) for a few hundred pixels.
constexpr double kMinVarianceRatio = 0.7;
constexpr double kMaxVarianceRatio = 1.4;

struct FurnaceCase {
    const char* scene;
    uint32_t size;
    uint32_t spp;
};

void checkFurnace(FurnaceTest& test, const FurnaceCase& c) {
    SCOPED_TRACE(c.scene);
    const scene::Scene scene = loadBuiltin(c.scene, c.size, c.size);
    ASSERT_FALSE(scene.materials.empty());
    const scene::Material& material = scene.materials.front();
    for (const scene::Material& other : scene.materials) {
        ASSERT_EQ(other.baseColor, material.baseColor) << "a furnace has one albedo";
        ASSERT_EQ(other.emission, material.emission) << "a furnace has one emission";
    }
    gi::PathTracerSettings settings;
    settings.maxBounces = 1u << 16; // truncation bias rho^65537: nothing; roulette ends the paths
    const gi::PathTracerResult result = test.render(scene, settings, c.spp);
    EXPECT_EQ(result.nonFiniteSamples, 0u);

    const char* channels[3][2] = {{"R", "variance.R"}, {"G", "variance.G"}, {"B", "variance.B"}};
    for (int k = 0; k < 3; ++k) {
        const double rho = material.baseColor[k];
        const double exact = material.emission[k] / (1.0 - rho);
        const ChannelMean m = channelMean(result.image, channels[k][0], channels[k][1]);
        EXPECT_NEAR(m.mean, exact, kSigmas * m.standardError)
            << channels[k][0] << ": mean " << m.mean << " vs Le/(1-rho) " << exact << ", standard error "
            << m.standardError;
        // The test has power: its tolerance is a small fraction of the answer.
        EXPECT_LT(m.standardError, 0.01 * exact) << channels[k][0];

        // The variance channel is right: the spread of the pixels around the exact answer
        // matches the variance they report (its mean over the pixels, pooled because a pixel's
        // own estimate correlates with its error in a skewed distribution).
        const auto values = result.image.channel(channels[k][0]);
        const auto variances = result.image.channel(channels[k][1]);
        double squaredError = 0.0, reportedVariance = 0.0;
        for (size_t i = 0; i < values.size(); ++i) {
            squaredError += (values[i] - exact) * (values[i] - exact);
            reportedVariance += variances[i];
        }
        const double ratio = squaredError / reportedVariance;
        std::printf("%s %s: mean %.5f (exact %.5f), standard error %.5f, spread/variance %.3f\n", c.scene,
                    channels[k][0], m.mean, exact, m.standardError, ratio);
        EXPECT_GT(ratio, kMinVarianceRatio)
            << channels[k][0] << ": pixels spread less than their variance says";
        EXPECT_LT(ratio, kMaxVarianceRatio)
            << channels[k][0] << ": pixels spread more than their variance says";
        size_t outliers = 0;
        const double pooledError = std::sqrt(reportedVariance / double(values.size()));
        for (float value : values) {
            outliers += std::abs(value - exact) > kSigmas * pooledError;
        }
        EXPECT_LE(double(outliers), kMaxOutlierFraction * double(values.size())) << channels[k][0];
    }
}

TEST_P(FurnaceTest, Albedo050MatchesLeOverOneMinusRho) {
    checkFurnace(*this, {"furnace_0.5", 24, 64});
}
TEST_P(FurnaceTest, Albedo080MatchesLeOverOneMinusRho) {
    checkFurnace(*this, {"furnace_0.8", 24, 64});
}
TEST_P(FurnaceTest, Albedo095MatchesLeOverOneMinusRho) {
    checkFurnace(*this, {"furnace_0.95", 16, 64});
}
TEST_P(FurnaceTest, Albedo099MatchesLeOverOneMinusRho) {
    checkFurnace(*this, {"furnace_0.99", 16, 64});
}

// The bounce limit truncates the series: with at most N scattering events the furnace gives
// Le (1 + rho + ... + rho^N) exactly (Russian roulette stays unbiased underneath).
TEST_P(FurnaceTest, BounceLimitTruncatesTheSeries) {
    const scene::Scene scene = loadBuiltin("furnace_0.5", 16, 16);
    const double rho = scene.materials.front().baseColor.r;
    const double le = scene.materials.front().emission.r;
    for (uint32_t bounces : {0u, 1u, 3u}) {
        SCOPED_TRACE("max bounces " + std::to_string(bounces));
        gi::PathTracerSettings settings;
        settings.maxBounces = bounces;
        const gi::PathTracerResult result = render(scene, settings, 32);
        const double exact = le * (1.0 - std::pow(rho, bounces + 1)) / (1.0 - rho);
        const ChannelMean m = channelMean(result.image, "R", "variance.R");
        std::printf("furnace_0.5, %u bounces: mean %.5f (exact %.5f), standard error %.5f\n", bounces, m.mean,
                    exact, m.standardError);
        EXPECT_NEAR(m.mean, exact, kSigmas * m.standardError + 1e-6 * exact);
        EXPECT_LT(m.standardError, 0.01 * exact);
    }
}

LUMINA_INSTANTIATE_GPU_TEST(FurnaceTest);

} // namespace
} // namespace lumina::test
