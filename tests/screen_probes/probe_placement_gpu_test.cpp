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
    EXPECT_GE(valid, r.probeCount / 8) << "the box";
    EXPECT_GE(sky, r.probeCount / 4) << "the sky around it";
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
        "screen probes: placement",      "screen probes: brdf pdf",        "screen probes: lighting pdf",
        "screen probes: mis directions", "screen probes: trace far field", "screen probes: shade rays",
        "screen probes: composite",      "screen probes: temporal",        "screen probes: spatial filter",
        "screen probes: sh irradiance",  "screen probes: final gather",    "screen probes: screen temporal"};
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
