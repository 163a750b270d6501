// The octahedral maps of the screen probes (shaders/screen_probes/octahedral_shared.h), through
// their C++ side: round trips, solid angles, the bordered tile's seams, the probe frame.
#include "shaders/screen_probes/octahedral_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

namespace lumina::test {
namespace {

using gpu::float2;
using gpu::float3;

constexpr float kPi = std::numbers::pi_v<float>;

float3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return glm::normalize(float3(g(rng), g(rng), g(rng)));
}

TEST(Octahedral, FullMapRoundTripsEveryDirection) {
    std::mt19937 rng(1);
    for (int i = 0; i < 10000; ++i) {
        const float3 d = randomDirection(rng);
        const float2 e = gpu::octEncode(d);
        ASSERT_LE(std::abs(e.x), 1.0f + 1e-6f);
        ASSERT_LE(std::abs(e.y), 1.0f + 1e-6f);
        const float3 back = gpu::octDecode(e);
        ASSERT_NEAR(glm::length(back - d), 0.0f, 2e-6f) << d.x << " " << d.y << " " << d.z;
    }
    // The poles and the seam's edge midpoints.
    EXPECT_NEAR(glm::length(gpu::octDecode(float2(0.0f, 0.0f)) - float3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(gpu::octDecode(float2(1.0f, 1.0f)) - float3(0, 0, -1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(gpu::octDecode(float2(1.0f, 0.0f)) - float3(1, 0, 0)), 0.0f, 1e-6f);
}

TEST(Octahedral, HemiMapRoundTripsTheUpperHemisphereAndCoversTheSquare) {
    std::mt19937 rng(2);
    for (int i = 0; i < 10000; ++i) {
        float3 d = randomDirection(rng);
        d.z = std::abs(d.z);
        const float2 e = gpu::hemiOctEncode(d);
        ASSERT_LE(std::abs(e.x), 1.0f + 1e-6f);
        ASSERT_LE(std::abs(e.y), 1.0f + 1e-6f);
        ASSERT_NEAR(glm::length(gpu::hemiOctDecode(e) - d), 0.0f, 2e-6f);
    }
    // Every corner of the square is on the horizon, the centre is the normal.
    for (const float2 corner : {float2(1, 1), float2(-1, 1), float2(1, -1), float2(-1, -1)}) {
        EXPECT_NEAR(gpu::hemiOctDecode(corner).z, 0.0f, 1e-6f);
    }
    EXPECT_NEAR(gpu::hemiOctDecode(float2(0, 0)).z, 1.0f, 1e-6f);
}

TEST(Octahedral, TexelSolidAnglesSumToTheHemisphereAndTheJacobianToTheSphere) {
    const uint32_t n = LUMINA_SP_OCT_SIZE;
    float hemi = 0.0f, smallest = 1e9f, largest = 0.0f;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            const float a = gpu::hemiOctTexelSolidAngle(x, y, n);
            hemi += a;
            smallest = std::min(smallest, a);
            largest = std::max(largest, a);
        }
    }
    EXPECT_NEAR(hemi, 2.0f * kPi, 2e-3f * 2.0f * kPi);
    // Octahedral maps are not equal-area, but close enough for 64 texels: the largest hemi texel
    // (at the normal) is 3.2x the smallest (at the horizon's corners).
    EXPECT_LT(largest / smallest, 3.5f);
    // The full map's Jacobian over a fine grid integrates to 4 pi.
    const int m = 512;
    double full = 0.0;
    for (int j = 0; j < m; ++j) {
        for (int i = 0; i < m; ++i) {
            full += gpu::octJacobian(float2(-1.0f + (i + 0.5f) * 2.0f / m, -1.0f + (j + 0.5f) * 2.0f / m));
        }
    }
    EXPECT_NEAR(full * (4.0 / (double(m) * m)), 4.0 * std::numbers::pi, 1e-3 * 4.0 * std::numbers::pi);
}

TEST(Octahedral, TexelOfAPositionIsTheTexelWhoseCentreItIsNear) {
    const uint32_t n = 8;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            const float2 c = gpu::octTexelCentre(x, y, n);
            EXPECT_EQ(gpu::octTexelOf(c, n), y * n + x);
            EXPECT_EQ(gpu::octTexelOf(c + float2(0.124f, -0.124f), n), y * n + x);
        }
    }
    EXPECT_EQ(gpu::octTexelOf(float2(1.0f, 1.0f), n), n * n - 1); // the edge belongs to the last texel
}

// Border texels repeat the interior across the seams (the DDGI rule): a left or right border
// texel shows the interior texel of its column edge in the mirrored row, top and bottom likewise,
// and each corner the diagonally opposite interior corner.
TEST(Octahedral, BorderTexelsShowTheInteriorTexelAcrossTheSeam) {
    const uint32_t n = LUMINA_SP_IRRADIANCE_SIZE;
    const uint32_t tile = n + 2;
    ASSERT_EQ(tile, uint32_t(LUMINA_SP_IRRADIANCE_TILE));
    auto centre = [&](uint32_t x, uint32_t y) { return gpu::octTexelCentre(x, y, n); };
    auto expectShows = [&](uint32_t tx, uint32_t ty, uint32_t ix, uint32_t iy) {
        const float2 e = gpu::octBorderedTexelPosition(tx, ty, n);
        const float2 c = centre(ix, iy);
        EXPECT_NEAR(e.x, c.x, 1e-6f) << "border " << tx << "," << ty;
        EXPECT_NEAR(e.y, c.y, 1e-6f) << "border " << tx << "," << ty;
    };
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            expectShows(x + 1, y + 1, x, y); // interior: itself
        }
    }
    for (uint32_t i = 0; i < n; ++i) {
        expectShows(0, i + 1, 0, n - 1 - i);            // left
        expectShows(tile - 1, i + 1, n - 1, n - 1 - i); // right
        expectShows(i + 1, 0, n - 1 - i, 0);            // top
        expectShows(i + 1, tile - 1, n - 1 - i, n - 1); // bottom
    }
    expectShows(0, 0, n - 1, n - 1);
    expectShows(tile - 1, 0, 0, n - 1);
    expectShows(0, tile - 1, n - 1, 0);
    expectShows(tile - 1, tile - 1, 0, 0);

    // ... which are neighbours on the sphere: a border texel's direction is no farther from its
    // interior neighbour in the tile than the widest step between interior neighbours.
    float widestInterior = 0.0f;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x + 1 < n; ++x) {
            widestInterior = std::max(widestInterior,
                                      std::acos(std::min(1.0f, glm::dot(gpu::octDecode(centre(x, y)),
                                                                        gpu::octDecode(centre(x + 1, y))))));
        }
    }
    for (uint32_t i = 1; i + 1 < tile; ++i) {
        const float3 border = gpu::octDecode(gpu::octBorderedTexelPosition(0, i, n));
        const float3 inside = gpu::octDecode(gpu::octBorderedTexelPosition(1, i, n));
        EXPECT_LE(std::acos(std::min(1.0f, glm::dot(border, inside))), widestInterior + 1e-4f) << "row " << i;
    }
}

TEST(Octahedral, ProbeFrameIsOrthonormalAndRightHandedForAnyNormal) {
    std::mt19937 rng(3);
    for (int i = 0; i < 2000; ++i) {
        float3 n = randomDirection(rng);
        if (i == 0) {
            n = float3(0, 0, -1); // the branchless basis's singular-looking case
        }
        const gpu::ProbeFrame f = gpu::probeFrame(n);
        EXPECT_NEAR(glm::length(f.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(f.bitangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.tangent, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.bitangent, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.tangent, f.bitangent), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(glm::cross(f.tangent, f.bitangent) - n), 0.0f, 1e-5f);
        const float3 d = randomDirection(rng);
        EXPECT_NEAR(glm::length(gpu::probeToWorld(f, gpu::worldToProbe(f, d)) - d), 0.0f, 1e-5f);
    }
}

} // namespace
} // namespace lumina::test
