// L2 spherical harmonics of the screen probes (shaders/screen_probes/sh_shared.h): projections
// of known radiance functions and the irradiance they give, on the CPU side of the shared code.
#include "shaders/screen_probes/octahedral_shared.h"
#include "shaders/screen_probes/sh_shared.h"

#include <functional>
#include <gtest/gtest.h>
#include <numbers>
#include <random>
#include <vector>

namespace lumina::test {
namespace {

using gpu::float2;
using gpu::float3;
using gpu::Sh9;

constexpr float kPi = std::numbers::pi_v<float>;

// Projects a scalar radiance function over the whole sphere (full octahedral midpoint grid).
Sh9 projectSphere(const std::function<float(float3)>& radiance, int m = 256) {
    Sh9 sh{};
    for (int j = 0; j < m; ++j) {
        for (int i = 0; i < m; ++i) {
            const float2 e(-1.0f + (i + 0.5f) * 2.0f / m, -1.0f + (j + 0.5f) * 2.0f / m);
            const float3 d = gpu::octDecode(e);
            const float w = gpu::octJacobian(e) * (4.0f / float(m * m)) * radiance(d);
            for (uint32_t k = 0; k < 9; ++k) {
                sh.v[k] += w * gpu::shBasis(k, d);
            }
        }
    }
    return sh;
}

float irradiance(const Sh9& sh, float3 n) {
    return gpu::shIrradiance(sh, sh, sh, n).x;
}

float3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return glm::normalize(float3(g(rng), g(rng), g(rng)));
}

TEST(ShL2, BasisIsOrthonormal) {
    for (uint32_t a = 0; a < 9; ++a) {
        for (uint32_t b = 0; b < 9; ++b) {
            const Sh9 sh = projectSphere([&](float3 d) { return gpu::shBasis(a, d); }, 128);
            EXPECT_NEAR(sh.v[b], a == b ? 1.0f : 0.0f, 2e-3f) << a << "," << b;
        }
    }
}

TEST(ShL2, ConstantRadianceGivesPiLEverywhere) {
    const float L = 2.5f;
    const Sh9 sh = projectSphere([&](float3) { return L; });
    std::mt19937 rng(4);
    for (int i = 0; i < 100; ++i) {
        EXPECT_NEAR(irradiance(sh, randomDirection(rng)), kPi * L, 1e-3f * kPi * L);
    }
}

// A cosine lobe of radiance max(0, a . w): by Funk-Hecke its L2 irradiance at n is
// sum_l A_l^2 (2l + 1) / (4 pi) P_l(a . n): 127 pi / 192 at n = a (exact: 2 pi / 3, the L2
// truncation loses 0.8%), and -pi / 192 at n = -a, which the reconstruction clamps to 0.
TEST(ShL2, CosineLobeMatchesFunkHeckeAndClampsItsNegativeRinging) {
    const float3 a = glm::normalize(float3(0.3f, -0.5f, 0.8f));
    const Sh9 sh = projectSphere([&](float3 d) { return std::max(0.0f, glm::dot(a, d)); });
    const float atLobe = irradiance(sh, a);
    EXPECT_NEAR(atLobe, 127.0f * kPi / 192.0f, 1e-3f * atLobe);
    EXPECT_NEAR(atLobe, 2.0f * kPi / 3.0f, 0.01f * 2.0f * kPi / 3.0f);
    // Unclamped value behind the lobe is negative: check the raw sum, then the clamp.
    float raw = 0.0f;
    for (uint32_t k = 0; k < 9; ++k) {
        raw += sh.v[k] * gpu::shBasis(k, -a) * gpu::shCosineBand(k);
    }
    EXPECT_NEAR(raw, -kPi / 192.0f, 2e-3f);
    EXPECT_EQ(irradiance(sh, -a), 0.0f);
}

// What probe_sh_irradiance does with a probe's hemi-octahedral map: uniform radiance L over the
// probe's hemisphere (nothing below) gives pi L at the probe normal, pi L / 2 on the horizon and 0
// straight below (E = pi L (1 + n . m) / 2: the step's L2 band vanishes).
TEST(ShL2, HemisphereMapOfUniformRadianceGivesPiLAtTheProbeNormal) {
    const float L = 1.75f;
    std::mt19937 rng(5);
    for (int probe = 0; probe < 20; ++probe) {
        const float3 n = randomDirection(rng);
        const gpu::ProbeFrame f = gpu::probeFrame(n);
        Sh9 sh{};
        for (uint32_t y = 0; y < LUMINA_SP_OCT_SIZE; ++y) {
            for (uint32_t x = 0; x < LUMINA_SP_OCT_SIZE; ++x) {
                const Sh9 texel = gpu::hemiOctTexelShIntegrals(x, y, LUMINA_SP_OCT_SIZE, f);
                for (uint32_t k = 0; k < 9; ++k) {
                    sh.v[k] += L * texel.v[k];
                }
            }
        }
        EXPECT_NEAR(irradiance(sh, n), kPi * L, 2e-3f * kPi * L) << "probe " << probe;
        EXPECT_NEAR(irradiance(sh, gpu::probeFrame(n).tangent), 0.5f * kPi * L, 5e-3f * kPi * L);
        EXPECT_NEAR(irradiance(sh, -n), 0.0f, 5e-3f * kPi * L);
    }
}

// The lower-hemisphere fill of probe_sh_irradiance (c_k = sum_t (L_t - M) I_tk + M S_k): any
// hemisphere radiance keeps its irradiance at the probe normal, and a direction below the tangent
// plane sees the probe's mean radiance M.
TEST(ShL2, MeanFillBelowTheProbeKeepsTheIrradianceAtItsNormal) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float3 n = glm::normalize(float3(0.2f, 0.9f, -0.4f));
    const gpu::ProbeFrame f = gpu::probeFrame(n);
    std::vector<float> radiance(LUMINA_SP_OCT_SIZE * LUMINA_SP_OCT_SIZE);
    float mean = 0.0f, solid = 0.0f;
    for (uint32_t t = 0; t < radiance.size(); ++t) {
        radiance[t] = 3.0f * unit(rng);
        const float a =
            gpu::hemiOctTexelSolidAngle(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
        mean += radiance[t] * a;
        solid += a;
    }
    mean /= solid;
    Sh9 hemi{}, filled{};
    filled.v[0] = mean * LUMINA_SH_SPHERE_INTEGRAL_0;
    for (uint32_t t = 0; t < radiance.size(); ++t) {
        const Sh9 in = gpu::hemiOctTexelShIntegrals(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE,
                                                    LUMINA_SP_OCT_SIZE, f);
        for (uint32_t k = 0; k < 9; ++k) {
            hemi.v[k] += radiance[t] * in.v[k];
            filled.v[k] += (radiance[t] - mean) * in.v[k];
        }
    }
    EXPECT_NEAR(irradiance(filled, n), irradiance(hemi, n), 2e-3f * irradiance(hemi, n));
    // Straight below, the hemisphere alone gives (about) nothing; the fill gives pi M there.
    EXPECT_NEAR(irradiance(filled, -n), kPi * mean + irradiance(hemi, -n), 0.02f * kPi * mean);
}

} // namespace
} // namespace lumina::test
