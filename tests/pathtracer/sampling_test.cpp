// The path tracer's random numbers and sampling routines (shaders/pathtracer/random_shared.h)
// evaluated in C++: deterministic per (seed, pixel, sample), uniform, and each sampler with
// the density it claims.
#include "gi/pathtracer/path_tracer.h"
#include "shaders/pathtracer/random_shared.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace lumina::gpu {
namespace {

TEST(PathTracerRandom, DependsOnlyOnSeedPixelAndSample) {
    PtRng a = ptRngCreate(1, 2, 3), b = ptRngCreate(1, 2, 3);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(ptRngNextUint(a), ptRngNextUint(b));
    }
    const uint first = ptRngNextUint(a);
    for (const PtRng& other : {ptRngCreate(2, 2, 3), ptRngCreate(1, 3, 3), ptRngCreate(1, 2, 4)}) {
        PtRng copy = other;
        EXPECT_NE(ptRngNextUint(copy), first);
    }
}

// Chi-square over 64 bins of the first numbers of many streams (as pixels draw them) and of
// one long stream: 63 degrees of freedom, 99.9th percentile ~103.4.
TEST(PathTracerRandom, UniformAcrossStreamsAndWithinOne) {
    constexpr int kBins = 64;
    constexpr int kDraws = 64 * 1000;
    auto chiSquare = [&](auto&& draw) {
        std::vector<int> counts(kBins, 0);
        for (int i = 0; i < kDraws; ++i) {
            const float u = draw(i);
            ASSERT_GE(u, 0.0f);
            ASSERT_LT(u, 1.0f);
            ++counts[int(u * kBins)];
        }
        double chi2 = 0.0;
        const double expected = double(kDraws) / kBins;
        for (int c : counts) {
            chi2 += (c - expected) * (c - expected) / expected;
        }
        EXPECT_LT(chi2, 103.4);
    };
    chiSquare([](int i) {
        PtRng rng = ptRngCreate(9, uint(i), 0);
        return ptRngNext(rng);
    });
    chiSquare([](int i) {
        PtRng rng = ptRngCreate(9, 0, uint(i));
        return ptRngNext(rng);
    });
    PtRng stream = ptRngCreate(9, 5, 5);
    chiSquare([&](int) { return ptRngNext(stream); });
}

TEST(PathTracerSampling, CosineHemisphereHasDensityCosOverPi) {
    // E[cos] = 2/3 and E[cos^2] = 1/2 under pdf cos/pi; all directions in the upper hemisphere.
    constexpr int kGrid = 300;
    double sumCos = 0.0, sumCos2 = 0.0;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            const float3 d = ptSampleCosineHemisphere((float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid);
            ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
            ASSERT_GE(d.z, 0.0f);
            sumCos += d.z;
            sumCos2 += d.z * d.z;
        }
    }
    EXPECT_NEAR(sumCos / (kGrid * kGrid), 2.0 / 3.0, 1e-3);
    EXPECT_NEAR(sumCos2 / (kGrid * kGrid), 0.5, 1e-3);
}

TEST(PathTracerSampling, TriangleSamplesAreUniformInArea) {
    // Uniform in area: the mean of the weights is the centroid's (1/3, 1/3), the mean of a
    // weight squared 1/6, and every sample lies inside.
    constexpr int kGrid = 300;
    double m1 = 0, m2 = 0, m11 = 0;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            const float2 b = ptSampleTriangle((float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid);
            ASSERT_GE(b.x, 0.0f);
            ASSERT_GE(b.y, 0.0f);
            ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
            m1 += b.x;
            m2 += b.y;
            m11 += b.x * b.x;
        }
    }
    const double n = kGrid * kGrid;
    EXPECT_NEAR(m1 / n, 1.0 / 3.0, 1e-3);
    EXPECT_NEAR(m2 / n, 1.0 / 3.0, 1e-3);
    EXPECT_NEAR(m11 / n, 1.0 / 6.0, 1e-3);
}

TEST(PathTracerSampling, PowerHeuristicWeightsSumToOne) {
    for (float a : {0.1f, 1.0f, 7.0f}) {
        for (float b : {0.0f, 0.5f, 3.0f}) {
            EXPECT_NEAR(ptPowerHeuristic(a, b) + ptPowerHeuristic(b, a), 1.0f, 1e-6f);
        }
    }
    EXPECT_EQ(ptPowerHeuristic(0.0f, 0.0f), 0.0f);
}

TEST(PathTracerStatistics, RelativeStandardErrorOfKnownAccumulation) {
    // Two pixels, 5 samples: m2 = variance * (n - 1); relative error sqrt(var / n) / sqrt(L^2 + 0.01).
    const std::vector<float4> mean = {float4(0, 0, 0, 1.0f), float4(0, 0, 0, 0.0f)};
    const std::vector<float4> m2 = {float4(0, 0, 0, 4.0f * 0.5f), float4(0, 0, 0, 4.0f * 0.02f)};
    const double expected =
        (std::sqrt(0.5 / 5.0) / std::sqrt(1.01) + std::sqrt(0.02 / 5.0) / std::sqrt(0.01)) / 2.0;
    EXPECT_NEAR(gi::relativeStandardError(mean, m2, 5), expected, 1e-6); // float inputs
    EXPECT_TRUE(std::isinf(gi::relativeStandardError(mean, m2, 1)));
}

} // namespace
} // namespace lumina::gpu
