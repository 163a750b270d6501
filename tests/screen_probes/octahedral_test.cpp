// The octahedral maps of the screen probes (shaders/screen_probes/octahedral_shared.h), through
// their C++ side: round trips, solid angles, the bordered tile's seams, the probe frame.
#include "shaders/screen_probes/octahedral_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

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

// Reading a bordered tile with bilinear filtering, as the final gather's sampler does (clamp
// addressing within the tile never triggers: positions stay inside the border).
float sampleTile(const std::vector<float>& tile, uint32_t n, float2 e) {
    const uint32_t size = n + 2;
    const float tx = 1.0f + (e.x * 0.5f + 0.5f) * float(n) - 0.5f;
    const float ty = 1.0f + (e.y * 0.5f + 0.5f) * float(n) - 0.5f;
    const auto x0 = uint32_t(std::floor(tx)), y0 = uint32_t(std::floor(ty));
    const float fx = tx - float(x0), fy = ty - float(y0);
    auto at = [&](uint32_t x, uint32_t y) {
        return tile[std::min(y, size - 1) * size + std::min(x, size - 1)];
    };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// The irradiance of uniform radiance over one hemisphere, pi (1 + n . m) / 2, stored in an 8 x 8
// bordered tile and read back bilinearly at every direction. Near the seams (|e| > 0.9 on either
// axis) the error stays as small as inside (mean 1.6%, worst 7.2% of pi): a border that merely
// repeated the nearest interior texel gives 3.2% and 11.4% there, one read from the wrong side
// of the seam far more. This is the interpolation error
// the final gather adds for directional light: 1.3% of pi on average, 7.6% at worst, where the
// octahedron's creases (e.x = 0 or e.y = 0) fold the map (docs/screen_probes.md).
TEST(Octahedral, BorderedTileReadsIrradianceContinuouslyAcrossTheSeams) {
    const uint32_t n = LUMINA_SP_IRRADIANCE_SIZE, size = n + 2;
    std::mt19937 rng(9);
    float worst = 0.0f, worstNearSeam = 0.0f;
    double sum = 0.0, sumNearSeam = 0.0;
    int count = 0, countNearSeam = 0;
    for (int lobe = 0; lobe < 8; ++lobe) {
        const float3 axis = randomDirection(rng);
        auto exact = [&](float3 m) { return kPi * 0.5f * (1.0f + glm::dot(axis, m)); };
        std::vector<float> tile(size * size);
        for (uint32_t y = 0; y < size; ++y) {
            for (uint32_t x = 0; x < size; ++x) {
                tile[y * size + x] = exact(gpu::octDecode(gpu::octBorderedTexelPosition(x, y, n)));
            }
        }
        for (int i = 0; i < 4000; ++i) {
            const float3 m = randomDirection(rng);
            const float2 e = gpu::octEncode(m);
            const float error = std::abs(sampleTile(tile, n, e) - exact(m)) / kPi;
            worst = std::max(worst, error);
            if (std::max(std::abs(e.x), std::abs(e.y)) > 0.9f) {
                worstNearSeam = std::max(worstNearSeam, error);
                sumNearSeam += error;
                ++countNearSeam;
            }
            sum += error;
            ++count;
        }
    }
    std::cout << "bordered tile: bilinear error mean " << sum / count << ", worst " << worst
              << ", worst near a seam " << worstNearSeam << " (of pi)\n";
    EXPECT_LT(sum / count, 0.015);
    EXPECT_LT(worst, 0.08f);
    EXPECT_LT(sumNearSeam / countNearSeam, 0.022);
    EXPECT_LT(worstNearSeam, 0.08f);
}

} // namespace
} // namespace lumina::test
