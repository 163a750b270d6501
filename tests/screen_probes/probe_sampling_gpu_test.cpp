// The ray directions on the GPU: the lighting PDF against last frame's history, the MIS
// directions against the CPU reference, a strategy without rays.
#include "gi/core/camera.h"
#include "gi/image/exr.h"
#include "gi/scene/scene_loader.h"
#include "gi/screen_probes/screen_probe_readback.h"
#include "shaders/common/conventions.h"
#include "shaders/screen_probes/probe_sampling_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/screen_probes/screen_probe_harness.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace lumina::test {
namespace {

using ProbeSamplingGpuTest = GpuTest;

// The lighting PDF: without history it is uniform in solid angle; from the second frame on it is
// (1 - floor) x luminance x solid angle of last frame's probe radiance, normalised, plus the floor
// spread uniformly. Walls are black here and the sky bright, so the table is far from uniform.
TEST_P(ProbeSamplingGpuTest, LightingPdfFollowsLastFramesRadianceAboveAFloor) {
    LUMINA_REQUIRE_KERNELS();
    gi::ScreenProbeSettings settings;
    settings.lightingPdfFloor = 0.2f;
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize, settings);
    harness.setSky(glm::vec3(2.0f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    std::vector<float> solid(LUMINA_SP_PROBE_TEXELS);
    float solidTotal = 0.0f;
    for (uint32_t t = 0; t < solid.size(); ++t) {
        solid[t] =
            gpu::hemiOctTexelSolidAngle(t % LUMINA_SP_OCT_SIZE, t / LUMINA_SP_OCT_SIZE, LUMINA_SP_OCT_SIZE);
        solidTotal += solid[t];
    }
    harness.render();
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[0]);
    auto pdf = harness.read<float>(r.lightingPdf);
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            ASSERT_NEAR(pdf[p * LUMINA_SP_PROBE_TEXELS + t], solid[t] / solidTotal, 1e-6f) << "probe " << p;
        }
    }
    const auto history = harness.read<gpu::float4>(r.history[0]);
    harness.render(); // same camera: every probe finds itself
    pdf = harness.read<float>(r.lightingPdf);
    const auto again = harness.read<gpu::ScreenProbe>(r.probes[1]);
    uint32_t skewed = 0, adaptive = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (again[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        const std::optional<uint32_t> old = sameProbeLastFrame(probes, again, p, r.uniformProbeCount);
        ASSERT_TRUE(old.has_value()) << "probe " << p << " was not placed last frame";
        adaptive += p >= r.uniformProbeCount;
        std::vector<float> mass(LUMINA_SP_PROBE_TEXELS, 0.0f);
        float massTotal = 0.0f, sum = 0.0f, lo = 1.0f, hi = 0.0f;
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            const gpu::float4 h = history[*old * LUMINA_SP_PROBE_TEXELS + t];
            const float l = gpu::spLightingPdfLuminance(gpu::luminance(gpu::float3(h)));
            mass[t] = h.w > 0.0f ? l * solid[t] : 0.0f;
            massTotal += mass[t];
        }
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            const float even = solid[t] / solidTotal;
            const float expected = massTotal > 0.0f ? 0.8f * mass[t] / massTotal + 0.2f * even : even;
            const float got = pdf[p * LUMINA_SP_PROBE_TEXELS + t];
            ASSERT_NEAR(got, expected, 1e-4f * expected + 1e-7f) << "probe " << p << " texel " << t;
            ASSERT_GE(got, 0.2f * even * (1.0f - 1e-4f)) << "the floor, probe " << p << " texel " << t;
            sum += got;
            lo = std::min(lo, got / even);
            hi = std::max(hi, got / even);
        }
        EXPECT_NEAR(sum, 1.0f, 1e-4f) << "probe " << p;
        skewed += hi > 4.0f * lo;
    }
    EXPECT_GT(skewed, 0u) << "probes that see both sky and black walls";
    EXPECT_GT(adaptive, 0u) << "adaptive probes (the box's silhouette, whose cell centres see the sky)";
}

// The MIS directions on the GPU are the CPU reference's (probe_sampling_shared.h: the same
// low-discrepancy point warped through the same tables, read back), lie in the texel they name,
// and carry the balance-heuristic weight of both tables; over frames, the BRDF rays fill the
// texels in proportion to the cosine table.
TEST_P(ProbeSamplingGpuTest, MisDirectionsAreTheTablesWarpedAndCarryTheirWeights) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32);
    harness.setSky(glm::vec3(3.0f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.1f, 0.1f, 0.1f, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const uint32_t nb = 32, nl = r.raysPerProbe - nb;
    std::vector<double> brdfHits(LUMINA_SP_PROBE_TEXELS, 0.0);
    std::vector<float> brdfTable;
    double brdfRays = 0.0;
    const uint32_t frames = 24;
    for (uint32_t frame = 0; frame < frames; ++frame) {
        harness.render();
        const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
        const auto rays = harness.read<gpu::ProbeRay>(r.rays);
        const auto brdf = harness.read<float>(r.brdfPdf);
        const auto light = harness.read<float>(r.lightingPdf);
        for (uint32_t p = 0; p < r.probeCount; ++p) {
            if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
                continue;
            }
            const gpu::ProbeFrame f = gpu::probeFrame(glm::vec3(probes[p].normal));
            gpu::SpTexelTable tb{}, tl{};
            for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
                tb.p[t / 4][t % 4] = brdf[p * 64 + t];
                tl.p[t / 4][t % 4] = light[p * 64 + t];
            }
            brdfTable.assign(brdf.begin() + p * 64, brdf.begin() + p * 64 + 64);
            for (uint32_t i = 0; i < r.raysPerProbe; ++i) {
                const gpu::ProbeRay& ray = rays[p * r.raysPerProbe + i];
                const bool fromBrdf = i < nb;
                ASSERT_EQ(ray.info.y, fromBrdf ? uint32_t(LUMINA_SP_STRATEGY_BRDF)
                                               : uint32_t(LUMINA_SP_STRATEGY_LIGHTING));
                const uint32_t seed = gpu::spProbeSeed(
                    p, r.uniformProbeCount, gpu::uint2(probes[p].info.y, probes[p].info.z), r.width);
                const glm::vec2 u =
                    gpu::spSamplePoint(fromBrdf ? i : i - nb, fromBrdf ? nb : nl, frame, seed, ray.info.y);
                const gpu::SpTableSample s = gpu::spSampleTable(fromBrdf ? tb : tl, u);
                const std::string where = "frame " + std::to_string(frame) + " probe " + std::to_string(p) +
                                          " ray " + std::to_string(i);
                ASSERT_EQ(ray.info.x, s.texel) << where;
                const glm::vec3 local = gpu::worldToProbe(f, glm::vec3(ray.directionAndWeight));
                ASSERT_NEAR(glm::length(local - gpu::hemiOctDecode(s.e)), 0.0f, 1e-5f) << where;
                ASSERT_EQ(gpu::octTexelOf(gpu::hemiOctEncode(gpu::hemiOctDecode(s.e)), LUMINA_SP_OCT_SIZE),
                          s.texel)
                    << where;
                const float pb = gpu::spTableDensity(brdf[p * 64 + s.texel], s.e, LUMINA_SP_OCT_SIZE);
                const float pl = gpu::spTableDensity(light[p * 64 + s.texel], s.e, LUMINA_SP_OCT_SIZE);
                ASSERT_NEAR(ray.directionAndWeight.w * (float(nb) * pb + float(nl) * pl), 1.0f, 1e-4f)
                    << where;
                if (fromBrdf) {
                    brdfHits[s.texel] += 1.0;
                    brdfRays += 1.0;
                }
            }
        }
    }
    ASSERT_GT(brdfRays, 0.0);
    for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
        const double expected = brdfTable[t] * brdfRays;
        EXPECT_NEAR(brdfHits[t], expected, 3.0 * std::sqrt(expected) + 1.0) << "texel " << t;
    }
}

// One strategy only: the other's table is not made (its pass is skipped with the reason) and the
// furnace still gives pi L, so the weights leave the unused table out.
TEST_P(ProbeSamplingGpuTest, AStrategyWithoutRaysSkipsItsTable) {
    LUMINA_REQUIRE_KERNELS();
    for (const float fraction : {0.0f, 1.0f}) {
        gi::ScreenProbeSettings settings;
        settings.brdfRayFraction = fraction;
        const glm::vec3 L(0.4f);
        ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 32, 32,
                                   settings);
        harness.setSky(L);
        harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, 1.0f); });
        const std::vector<std::string> passes = harness.render();
        const std::string skippedPass =
            fraction == 0.0f ? gi::ProbeBrdfPdfPass::kName : gi::ProbeLightingPdfPass::kName;
        const std::string reason = fraction == 0.0f ? "no BRDF rays: all 64 from the lighting PDF"
                                                    : "no lighting rays: all 64 from the BRDF PDF";
        EXPECT_EQ(std::count(passes.begin(), passes.end(), skippedPass), 0) << skippedPass;
        // The deferred renderer skips its sun shadow too, and the near field has no surface cache.
        std::vector<gi::SkippedPass> ours;
        std::copy_if(harness.skipped().begin(), harness.skipped().end(), std::back_inserter(ours),
                     [](const gi::SkippedPass& skip) {
                         return skip.pass.rfind("screen probes: ", 0) == 0 &&
                                skip.pass != gi::ProbeTraceNearFieldPass::kName;
                     });
        ASSERT_EQ(ours.size(), 1u);
        EXPECT_EQ(ours[0].pass, skippedPass);
        EXPECT_EQ(ours[0].reason, reason);
        harness.render();
        const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
        const image::Image result = harness.read(harness.probes().irradiance());
        for (uint32_t y = 0; y < 32; ++y) {
            for (uint32_t x = 0; x < 32; ++x) {
                if (normal.at("A", x, y) > 0.0f) {
                    ASSERT_NEAR(result.rgbAt(x, y).g, kPi * L.y, 0.005f * kPi * L.y)
                        << fraction << " at " << x << "," << y;
                }
            }
        }
    }
}

LUMINA_INSTANTIATE_GPU_TEST(ProbeSamplingGpuTest);

} // namespace
} // namespace lumina::test
