// Ray directions of the screen probes (shaders/screen_probes/probe_sampling_shared.h), made the
// way probe_ray_generation.hlsl makes them: balance-heuristic weights, the density of the
// low-discrepancy table samples, and estimates of known integrals.
#include "shaders/screen_probes/probe_sampling_shared.h"

#include <functional>
#include <gtest/gtest.h>
#include <numbers>
#include <random>
#include <vector>

namespace lumina::test {
namespace {

using gpu::float2;
using gpu::float3;

constexpr double kPi = std::numbers::pi;
constexpr uint32_t kN = LUMINA_SP_OCT_SIZE;

gpu::SpTexelTable tableOf(const std::vector<float>& p) {
    gpu::SpTexelTable t{};
    for (uint32_t i = 0; i < LUMINA_SP_TABLE_SIZE; ++i) {
        t.p[i / 4][i % 4] = p[i];
    }
    return t;
}

// The BRDF table as probe_brdf_pdf.hlsl writes it.
std::vector<float> cosineTable() {
    std::vector<float> p(LUMINA_SP_TABLE_SIZE);
    double total = 0.0;
    for (uint32_t i = 0; i < p.size(); ++i) {
        p[i] = gpu::hemiOctTexelCosineMass(i % kN, i / kN, kN);
        total += p[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-3); // the quadrature of cos / pi over the hemisphere
    for (float& v : p) {
        v = float(v / total);
    }
    return p;
}

// A lighting table as probe_lighting_pdf.hlsl writes it: a bright patch plus a 10% uniform floor.
std::vector<float> lightingTable(float floorShare = 0.1f) {
    std::vector<float> mass(LUMINA_SP_TABLE_SIZE), solid(LUMINA_SP_TABLE_SIZE);
    double massTotal = 0.0, solidTotal = 0.0;
    for (uint32_t i = 0; i < mass.size(); ++i) {
        solid[i] = gpu::hemiOctTexelSolidAngle(i % kN, i / kN, kN);
        const float luminance = (i % kN < 2 && i / kN < 3) ? 50.0f : (i % 7 == 0 ? 0.0f : 1.0f);
        mass[i] = luminance * solid[i];
        massTotal += mass[i];
        solidTotal += solid[i];
    }
    std::vector<float> p(mass.size());
    for (uint32_t i = 0; i < p.size(); ++i) {
        p[i] = float((1.0 - floorShare) * mass[i] / massTotal + floorShare * solid[i] / solidTotal);
    }
    return p;
}

struct Ray {
    float3 local; // direction in the probe frame (+z the normal)
    float weight;
    uint32_t texel;
};

// One frame of one probe's rays, as the kernel makes them.
std::vector<Ray> makeRays(const std::vector<float>& brdf, const std::vector<float>& light, uint32_t nBrdf,
                          uint32_t nLight, uint32_t frame, uint32_t probe) {
    const gpu::SpTexelTable tb = tableOf(brdf), tl = tableOf(light);
    std::vector<Ray> rays;
    for (uint32_t r = 0; r < nBrdf + nLight; ++r) {
        const bool fromBrdf = r < nBrdf;
        const uint32_t local = fromBrdf ? r : r - nBrdf;
        const float2 u =
            gpu::spSamplePoint(local, fromBrdf ? nBrdf : nLight, frame, probe, fromBrdf ? 0u : 1u);
        const gpu::SpTableSample s = gpu::spSampleTable(fromBrdf ? tb : tl, u);
        const float pb = gpu::spTableDensity(brdf[s.texel], s.e, kN);
        const float pl = gpu::spTableDensity(light[s.texel], s.e, kN);
        rays.push_back(
            {gpu::hemiOctDecode(s.e), gpu::spMisWeight(float(nBrdf), pb, float(nLight), pl), s.texel});
    }
    return rays;
}

TEST(ProbeSampling, BalanceHeuristicSharesSumToOneAndWeightsInvertTheMixture) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> pdf(0.0f, 5.0f);
    std::uniform_int_distribution<int> count(0, 64);
    for (int i = 0; i < 1000; ++i) {
        const float pb = pdf(rng), pl = pdf(rng);
        const auto nb = float(count(rng)), nl = float(64 - nb);
        const float sum = nb * pb + nl * pl;
        if (sum <= 0.0f) {
            EXPECT_EQ(gpu::spMisWeight(nb, pb, nl, pl), 0.0f);
            continue;
        }
        EXPECT_NEAR(gpu::spBalanceShare(nb, pb, nl, pl) + gpu::spBalanceShare(nl, pl, nb, pb), 1.0f, 1e-6f);
        EXPECT_NEAR(gpu::spMisWeight(nb, pb, nl, pl) * sum, 1.0f, 1e-6f);
    }
}

// Sum over rays of weight x f estimates the integral of f over the hemisphere: 2 pi for 1, pi for
// cos, 2 pi / 3 for cos^2. Low discrepancy keeps one frame close; 64 frames closer.
TEST(ProbeSampling, WeightedRaysEstimateHemisphereIntegrals) {
    const std::vector<float> brdf = cosineTable(), light = lightingTable();
    struct Case {
        const char* name;
        std::function<double(float3)> f;
        double exact;
    };
    const Case cases[] = {{"one", [](float3) { return 1.0; }, 2.0 * kPi},
                          {"cos", [](float3 d) { return double(d.z); }, kPi},
                          {"cos^2", [](float3 d) { return double(d.z) * d.z; }, 2.0 * kPi / 3.0}};
    for (const Case& c : cases) {
        double sumFrames = 0.0, worstFrame = 0.0;
        const int frames = 64;
        for (int frame = 0; frame < frames; ++frame) {
            double estimate = 0.0;
            for (const Ray& ray : makeRays(brdf, light, 32, 32, uint32_t(frame), 17)) {
                estimate += ray.weight * c.f(ray.local);
            }
            worstFrame = std::max(worstFrame, std::abs(estimate / c.exact - 1.0));
            sumFrames += estimate;
        }
        EXPECT_NEAR(sumFrames / frames / c.exact, 1.0, 0.01) << c.name;
        EXPECT_LT(worstFrame, 0.2) << c.name;
    }
}

// The directions' density is the table's: over many frames (each a rotated low-discrepancy set)
// each texel is chosen in proportion to its probability, and within a texel the points are
// uniform in e (their mean is the texel centre).
TEST(ProbeSampling, LowDiscrepancyDirectionsFollowTheirTable) {
    for (const bool brdfStrategy : {true, false}) {
        const std::vector<float> table = brdfStrategy ? cosineTable() : lightingTable();
        const gpu::SpTexelTable t = tableOf(table);
        std::vector<double> hits(LUMINA_SP_TABLE_SIZE, 0.0);
        std::vector<float2> meanE(LUMINA_SP_TABLE_SIZE, float2(0.0f));
        const uint32_t n = 64, frames = 512;
        for (uint32_t frame = 0; frame < frames; ++frame) {
            for (uint32_t i = 0; i < n; ++i) {
                const gpu::SpTableSample s =
                    gpu::spSampleTable(t, gpu::spSamplePoint(i, n, frame, 3u, brdfStrategy ? 0u : 1u));
                ASSERT_GT(s.probability, 0.0f);
                ASSERT_EQ(gpu::octTexelOf(s.e, kN), s.texel);
                hits[s.texel] += 1.0;
                meanE[s.texel] += s.e;
            }
        }
        const double total = double(n) * frames;
        for (uint32_t i = 0; i < hits.size(); ++i) {
            const double expected = table[i] * total;
            // Stratified sampling beats Poisson noise: within 3 sigma of a binomial, plus one sample.
            EXPECT_NEAR(hits[i], expected, 3.0 * std::sqrt(expected) + 1.0)
                << "texel " << i << (brdfStrategy ? " brdf" : " lighting");
            if (hits[i] > 100) {
                const float2 centre = gpu::octTexelCentre(i % kN, i / kN, kN);
                const float2 mean = meanE[i] / float(hits[i]);
                EXPECT_NEAR(mean.x, centre.x, 0.03f) << "texel " << i;
                EXPECT_NEAR(mean.y, centre.y, 0.03f) << "texel " << i;
            }
        }
    }
}

// The BRDF strategy alone draws texels by their cosine mass and points uniformly in e within a
// texel (piecewise, not exactly cos / pi inside a texel: the MIS weights use this density, so
// estimates stay unbiased). The mean cosine of its samples is that density's expectation,
// sum_T P_T x mean over T of cos, and within 3% of the true cosine lobe's 2/3.
TEST(ProbeSampling, BrdfTableSamplesFollowTheCosineTableDensity) {
    const std::vector<float> table = cosineTable();
    const gpu::SpTexelTable t = tableOf(table);
    double expected = 0.0;
    const int m = 32; // sub-samples per texel edge
    for (uint32_t i = 0; i < table.size(); ++i) {
        double mean = 0.0;
        for (int b = 0; b < m; ++b) {
            for (int a = 0; a < m; ++a) {
                const float2 e(-1.0f + 2.0f / kN * (float(i % kN) + (a + 0.5f) / m),
                               -1.0f + 2.0f / kN * (float(i / kN) + (b + 0.5f) / m));
                mean += gpu::hemiOctDecode(e).z;
            }
        }
        expected += table[i] * mean / (m * m);
    }
    double sum = 0.0;
    const uint32_t n = 64, frames = 256;
    for (uint32_t frame = 0; frame < frames; ++frame) {
        for (uint32_t i = 0; i < n; ++i) {
            sum += gpu::hemiOctDecode(gpu::spSampleTable(t, gpu::spSamplePoint(i, n, frame, 9u, 0u)).e).z;
        }
    }
    EXPECT_NEAR(sum / (double(n) * frames), expected, 2e-3);
    EXPECT_NEAR(expected, 2.0 / 3.0, 0.03 * 2.0 / 3.0);
}

// The per-frame rotation is the R2 sequence, exact modulo 1 at any frame count: consecutive
// frames step by (0.7549, 0.5698) mod 1 at frame 10 as at frame 2^31.
TEST(ProbeSampling, FrameRotationStaysTheR2StepAfterBillionsOfFrames) {
    for (const uint32_t frame : {10u, 1u << 20, 1u << 31}) {
        const float2 a = gpu::spRotation(frame, 4u, 1u), b = gpu::spRotation(frame + 1, 4u, 1u);
        const auto step = [](float from, float to) { return to - from + (to < from ? 1.0f : 0.0f); };
        EXPECT_NEAR(step(a.x, b.x), 0.7548777f, 1e-6f) << "frame " << frame;
        EXPECT_NEAR(step(a.y, b.y), 0.5698403f, 1e-6f) << "frame " << frame;
    }
}

TEST(ProbeSampling, JitterChangesEveryFrameAndProbeButStaysInTheUnitSquare) {
    for (uint32_t frame = 0; frame < 100; ++frame) {
        const float2 a = gpu::spRotation(frame, 5u, 0u), b = gpu::spRotation(frame + 1, 5u, 0u);
        const float2 c = gpu::spRotation(frame, 6u, 0u);
        EXPECT_NE(a, b);
        EXPECT_NE(a, c);
        for (uint32_t i = 0; i < 64; ++i) {
            const float2 u = gpu::spSamplePoint(i, 64, frame, 5u, 1u);
            ASSERT_GE(u.x, 0.0f);
            ASSERT_LT(u.x, 1.0f);
            ASSERT_GE(u.y, 0.0f);
            ASSERT_LT(u.y, 1.0f);
        }
    }
}

} // namespace
} // namespace lumina::test
