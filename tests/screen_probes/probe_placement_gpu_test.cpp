// Placement on the GPU (lavapipe in CI; validation and synchronization validation on): probes at
// the GBuffer surface of their cell centre, sky probes invalid and skipped by every later pass,
// every pass named and timed, bad inputs refused.
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

using ProbePlacementGpuTest = GpuTest;

bool isNaNBits(float v, uint32_t bits) {
    uint32_t got;
    std::memcpy(&got, &v, 4);
    return got == bits;
}

TEST_P(ProbePlacementGpuTest, PlacementPutsProbesOnTheGBufferSurfaceAndMarksSkyInvalid) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.render();
    const gi::ScreenProbeResources& r = harness.probes().resources();
    ASSERT_EQ(r.gridWidth, kSize / 8);
    ASSERT_EQ(r.gridHeight, kSize / 8);
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
    ASSERT_EQ(probes.size(), r.probeCount);
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image position = harness.read(harness.renderer().gbuffer().position);
    uint32_t valid = 0, sky = 0;
    for (uint32_t y = 0; y < r.gridHeight; ++y) {
        for (uint32_t x = 0; x < r.gridWidth; ++x) {
            const gpu::ScreenProbe& p = probes[y * r.gridWidth + x];
            const uint32_t px = x * 8 + 4, py = y * 8 + 4;
            const std::string where = "probe " + std::to_string(x) + "," + std::to_string(y);
            EXPECT_EQ(p.info.y, px) << where;
            EXPECT_EQ(p.info.z, py) << where;
            const bool surface = normal.at("A", px, py) > 0.0f;
            EXPECT_EQ(p.info.x, surface ? uint32_t(LUMINA_SP_PROBE_VALID) : 0u) << where;
            if (!surface) {
                ++sky;
                continue;
            }
            ++valid;
            const image::Rgb g = position.rgbAt(px, py);
            EXPECT_EQ(p.positionAndDepth.x, g.r) << where;
            EXPECT_EQ(p.positionAndDepth.y, g.g) << where;
            EXPECT_EQ(p.positionAndDepth.z, g.b) << where;
            EXPECT_EQ(p.positionAndDepth.w, position.at("A", px, py)) << where << ": view depth";
            EXPECT_GT(p.positionAndDepth.w, 0.0f) << where;
            const image::Rgb n = normal.rgbAt(px, py);
            const glm::vec3 expected = glm::normalize(glm::vec3(n.r, n.g, n.b));
            EXPECT_NEAR(glm::length(glm::vec3(p.normal) - expected), 0.0f, 1e-5f) << where;
        }
    }
    EXPECT_GE(valid, r.uniformProbeCount / 8) << "the box";
    EXPECT_GE(sky, r.uniformProbeCount / 4) << "the sky around it";
}

// A pixel's coverage: the best surface weight (probeSurfaceWeight) among the valid uniform probes
// at the corners of its cell, as the adaptive placement and the gather compute it.
float uniformCoverage(const std::vector<gpu::ScreenProbe>& probes, const gi::ScreenProbeResources& r,
                      const gi::ScreenProbeSettings& s, glm::uvec2 pixel, glm::vec4 position, glm::vec3 n) {
    const glm::vec2 g = (glm::vec2(pixel) + 0.5f) / float(s.probeSpacing) - 0.5f;
    const glm::ivec2 base(glm::floor(g));
    float best = 0.0f;
    for (int k = 0; k < 4; ++k) {
        const glm::ivec2 cell = glm::clamp(base + glm::ivec2(k & 1, k >> 1), glm::ivec2(0),
                                           glm::ivec2(r.gridWidth, r.gridHeight) - 1);
        const gpu::ScreenProbe& p = probes[size_t(cell.y) * r.gridWidth + size_t(cell.x)];
        if (p.info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        const float plane =
            std::abs(glm::dot(glm::vec3(position) - glm::vec3(p.positionAndDepth), glm::vec3(p.normal)));
        const float weight =
            std::exp(-plane / (s.filterPlaneScale * position.w)) *
            std::pow(std::clamp(glm::dot(n, glm::vec3(p.normal)), 0.0f, 1.0f), s.filterNormalPower);
        best = std::max(best, weight);
    }
    return best;
}

// Adaptive placement, checked against the CPU: each adaptive tile whose least covered surface pixel
// is covered below LUMINA_SP_ADAPTIVE_COVERAGE holds one adaptive probe, at that pixel (its GBuffer
// position and normal), in the next slot of the adaptive rows in tile order (so the same tiles get
// the same slots on every run); a tile whose pixels are all covered holds none; no slot is valid
// that no tile names; the count reported is the tiles that wanted one. cornellWithSky gives both: the
// box's silhouette, whose cell centres see the sky, and its blocks' narrow faces.
TEST_P(ProbePlacementGpuTest, AdaptiveProbesGoWhereNoUniformProbeCoversAPixel) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.render();
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const gi::ScreenProbeSettings& s = harness.probes().settings();
    ASSERT_EQ(r.adaptiveSpacing, 4u);
    ASSERT_EQ(r.adaptiveRows, 2u) << "a quarter of 8 rows";
    const uint32_t c = harness.probes().current();
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[c]);
    const auto index = harness.read<uint32_t>(r.adaptiveIndex[c]);
    ASSERT_EQ(index.size(), size_t(r.adaptiveWidth) * r.adaptiveHeight);
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image position = harness.read(harness.renderer().gbuffer().position);
    std::vector<bool> named(r.probeCount, false);
    uint32_t placed = 0, uncovered = 0, covered = 0;
    for (uint32_t ty = 0; ty < r.adaptiveHeight; ++ty) {
        for (uint32_t tx = 0; tx < r.adaptiveWidth; ++tx) {
            float worst = 2.0f;
            for (uint32_t i = 0; i < r.adaptiveSpacing * r.adaptiveSpacing; ++i) {
                const glm::uvec2 px(tx * r.adaptiveSpacing + i % r.adaptiveSpacing,
                                    ty * r.adaptiveSpacing + i / r.adaptiveSpacing);
                if (normal.at("A", px.x, px.y) <= 0.0f) {
                    continue;
                }
                const image::Rgb g = position.rgbAt(px.x, px.y), n = normal.rgbAt(px.x, px.y);
                worst =
                    std::min(worst, uniformCoverage(probes, r, s, px,
                                                    glm::vec4(g.r, g.g, g.b, position.at("A", px.x, px.y)),
                                                    glm::normalize(glm::vec3(n.r, n.g, n.b))));
            }
            const std::string where = "tile " + std::to_string(tx) + "," + std::to_string(ty);
            const uint32_t slot = index[ty * r.adaptiveWidth + tx];
            // The GPU's exp and pow may round the other way within a hair of the threshold: either
            // answer, but a probe there still takes the next slot.
            if (std::abs(worst - LUMINA_SP_ADAPTIVE_COVERAGE) < 1e-3f) {
                if (slot != LUMINA_SP_NO_ADAPTIVE_PROBE) {
                    ASSERT_EQ(slot, r.uniformProbeCount + placed) << where;
                    named[slot] = true;
                    ++placed;
                }
                continue;
            }
            if (worst > LUMINA_SP_ADAPTIVE_COVERAGE) {
                ++covered;
                EXPECT_EQ(slot, LUMINA_SP_NO_ADAPTIVE_PROBE) << where << " is covered (" << worst << ")";
                continue;
            }
            ++uncovered;
            ASSERT_NE(slot, LUMINA_SP_NO_ADAPTIVE_PROBE) << where << " is not covered (" << worst << ")";
            ASSERT_EQ(slot, r.uniformProbeCount + placed) << where << ": slots follow tile order";
            ASSERT_LT(slot, r.probeCount) << where;
            ASSERT_FALSE(named[slot]) << where << ": slot " << slot << " named twice";
            named[slot] = true;
            ++placed;
            const gpu::ScreenProbe& p = probes[slot];
            ASSERT_EQ(p.info.x, uint32_t(LUMINA_SP_PROBE_VALID)) << where;
            ASSERT_EQ(p.info.y / r.adaptiveSpacing, tx) << where;
            ASSERT_EQ(p.info.z / r.adaptiveSpacing, ty) << where;
            const image::Rgb g = position.rgbAt(p.info.y, p.info.z), n = normal.rgbAt(p.info.y, p.info.z);
            EXPECT_EQ(glm::vec3(p.positionAndDepth), glm::vec3(g.r, g.g, g.b)) << where;
            const glm::vec4 at(g.r, g.g, g.b, position.at("A", p.info.y, p.info.z));
            const float own = uniformCoverage(probes, r, s, glm::uvec2(p.info.y, p.info.z), at,
                                              glm::normalize(glm::vec3(n.r, n.g, n.b)));
            EXPECT_NEAR(own, worst, 1e-4f) << where << ": the probe is not at the least covered pixel";
        }
    }
    for (uint32_t slot = r.uniformProbeCount; slot < r.probeCount; ++slot) {
        EXPECT_TRUE(named[slot] || probes[slot].info.x != LUMINA_SP_PROBE_VALID) << "slot " << slot;
    }
    EXPECT_GT(placed, 0u);
    EXPECT_EQ(harness.probes().adaptiveProbesWanted(device()), placed);
    EXPECT_LT(placed, r.probeCount - r.uniformProbeCount) << "the rows overflowed: tiles went without";
    EXPECT_GT(covered, uncovered) << "most of the image is covered by the uniform grid";
}

// With fewer adaptive slots than tiles that want one, the slots are shared evenly over the
// candidates in tile order (spAdaptiveShare): exactly as many kept as there are slots, each at its
// candidate's pixel, the last candidate, at the image's bottom, among them. Taken in tile order, the
// top rows would have had every slot.
TEST_P(ProbePlacementGpuTest, AdaptiveSlotsAreSharedEvenlyWhenMoreTilesWantOne) {
    LUMINA_REQUIRE_KERNELS();
    gi::ScreenProbeSettings settings;
    settings.adaptiveProbeFraction = 0.125f; // one row of 8 slots
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize, settings);
    harness.render();
    const gi::ScreenProbeResources& r = harness.probes().resources();
    ASSERT_EQ(r.adaptiveRows, 1u);
    const uint32_t slots = r.probeCount - r.uniformProbeCount;
    const uint32_t c = harness.probes().current();
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[c]);
    const auto index = harness.read<uint32_t>(r.adaptiveIndex[c]);
    const auto candidates = harness.read<uint32_t>(r.adaptiveCandidates);
    std::vector<uint32_t> wanting; // tiles in tile order
    for (uint32_t tile = 0; tile < candidates.size(); ++tile) {
        if (candidates[tile] != LUMINA_SP_NO_ADAPTIVE_PROBE) {
            wanting.push_back(tile);
        } else {
            EXPECT_EQ(index[tile], LUMINA_SP_NO_ADAPTIVE_PROBE) << "tile " << tile << " wants none";
        }
    }
    const auto wanted = uint32_t(wanting.size());
    ASSERT_GT(wanted, slots) << "the slots must overflow for this test";
    EXPECT_EQ(harness.probes().adaptiveProbesWanted(device()), wanted);
    uint32_t kept = 0;
    for (uint32_t rank = 0; rank < wanted; ++rank) {
        const uint32_t tile = wanting[rank];
        const std::string where = "tile " + std::to_string(tile) + ", rank " + std::to_string(rank);
        const uint64_t share = uint64_t(rank) * slots / wanted;
        if (uint64_t(rank + 1) * slots / wanted == share) {
            EXPECT_EQ(index[tile], LUMINA_SP_NO_ADAPTIVE_PROBE) << where << " goes without";
            continue;
        }
        ++kept;
        ASSERT_EQ(index[tile], r.uniformProbeCount + share) << where;
        const gpu::ScreenProbe& p = probes[index[tile]];
        EXPECT_EQ(p.info.x, uint32_t(LUMINA_SP_PROBE_VALID)) << where;
        EXPECT_EQ(p.info.y, candidates[tile] & 0xffffu) << where;
        EXPECT_EQ(p.info.z, candidates[tile] >> 16u) << where;
    }
    EXPECT_EQ(kept, slots);
    EXPECT_NE(index[wanting.back()], LUMINA_SP_NO_ADAPTIVE_PROBE)
        << "the bottom of the image keeps its share";
}

// Every pass runs under its name, in order; probes on the sky are skipped: none of their entries
// in any per-probe buffer is touched (each was filled with a NaN pattern first), while every entry
// of a valid probe is written and finite. Sky pixels gather nothing.
TEST_P(ProbePlacementGpuTest, EveryPassRunsTimedAndSkyProbesAreSkipped) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.setSky(glm::vec3(0.5f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.3f, 0.3f, 0.3f, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    constexpr uint32_t kSentinel = 0x7FC0DEADu; // a quiet NaN no pass writes
    {
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        for (const auto& buffer : {r.brdfPdf, r.lightingPdf, r.rays, r.hits, r.rayRadiance, r.frameRadiance,
                                   r.history[0], r.filtered, r.sh}) {
            list->fillBuffer(*buffer, kSentinel);
        }
        list->end();
        submitAndWait(*list);
    }
    const std::vector<std::string> passes = harness.render();
    const std::vector<std::string> expected = {
        "screen probes: placement",           "screen probes: adaptive placement",
        "screen probes: adaptive allocation", "screen probes: brdf pdf",
        "screen probes: lighting pdf",        "screen probes: mis directions",
        "screen probes: trace far field",     "screen probes: shade rays",
        "screen probes: composite",           "screen probes: temporal",
        "screen probes: spatial filter",      "screen probes: sh irradiance",
        "screen probes: final gather",        "screen probes: screen temporal"};
    std::vector<std::string> ours;
    std::copy_if(passes.begin(), passes.end(), std::back_inserter(ours),
                 [](const std::string& name) { return name.rfind("screen probes: ", 0) == 0; });
    EXPECT_EQ(ours, expected);

    ASSERT_EQ(harness.probes().current(), 0u);
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[0]);
    struct Checked {
        const char* name;
        std::vector<float> values;
        size_t perProbe;
    };
    const size_t texels = LUMINA_SP_PROBE_TEXELS, rayFloats = size_t(r.raysPerProbe);
    const Checked buffers[] = {
        {"brdf pdf", harness.read<float>(r.brdfPdf), texels},
        {"lighting pdf", harness.read<float>(r.lightingPdf), texels},
        {"rays", harness.read<float>(r.rays), rayFloats * 8},
        {"hits", harness.read<float>(r.hits), rayFloats * 12},
        {"ray radiance", harness.read<float>(r.rayRadiance), rayFloats * 4},
        {"frame radiance", harness.read<float>(r.frameRadiance), texels * 4},
        {"history", harness.read<float>(r.history[0]), texels * 4},
        {"filtered", harness.read<float>(r.filtered), texels * 4},
        {"sh", harness.read<float>(r.sh), size_t(LUMINA_SH_COEFFICIENTS) * 4},
    };
    uint32_t sky = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        const bool valid = probes[p].info.x == LUMINA_SP_PROBE_VALID;
        sky += valid ? 0 : 1;
        for (const Checked& b : buffers) {
            ASSERT_EQ(b.values.size(), b.perProbe * r.probeCount) << b.name;
            for (size_t i = p * b.perProbe; i < (p + 1) * b.perProbe; ++i) {
                if (valid) {
                    // Rays and hits hold uint fields too: those only need to be written.
                    ASSERT_FALSE(isNaNBits(b.values[i], kSentinel))
                        << b.name << " probe " << p << " entry " << i;
                } else {
                    ASSERT_TRUE(isNaNBits(b.values[i], kSentinel))
                        << b.name << " sky probe " << p << " entry " << i;
                }
            }
        }
    }
    EXPECT_GT(sky, 0u);
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image gather = harness.read(r.gather);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (normal.at("A", x, y) == 0.0f) {
                const image::Rgb g = gather.rgbAt(x, y);
                ASSERT_EQ(g.r + g.g + g.b, 0.0f) << "sky pixel " << x << "," << y;
            }
        }
    }
}

TEST_P(ProbePlacementGpuTest, BadInputsAreRefusedByName) {
    EXPECT_THROW(gi::ScreenProbeGather(device(), 0, 64), std::invalid_argument);
    gi::ScreenProbeSettings bad;
    bad.raysPerProbe = 4;
    try {
        gi::ScreenProbeGather(device(), 64, 64, bad);
        ADD_FAILURE() << "accepted raysPerProbe = 4";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("raysPerProbe = 4"), std::string::npos) << e.what();
    }
}

LUMINA_INSTANTIATE_GPU_TEST(ProbePlacementGpuTest);

} // namespace
} // namespace lumina::test
