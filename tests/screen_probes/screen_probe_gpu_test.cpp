// The screen-probe gather on the GPU (lavapipe in CI), validation and synchronization validation
// on: placement against the GBuffer, sky probes skipped by every pass, the white furnace, the
// bound of temporal accumulation with NaN and Inf injected, and history across camera motion.
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

using ScreenProbeGpuTest = GpuTest;

constexpr uint32_t kSize = 64;
constexpr float kPi = std::numbers::pi_v<float>;

// cornell_box_point seen from farther back: the box fills the middle, the sky the rest.
scene::Scene cornellWithSky() {
    scene::Scene scene = scene::loadScene("cornell_box_point");
    scene.camera.position -= scene.camera.forward * 900.0f;
    return scene;
}

bool isNaNBits(float v, uint32_t bits) {
    uint32_t got;
    std::memcpy(&got, &v, 4);
    return got == bits;
}

TEST_P(ScreenProbeGpuTest, PlacementPutsProbesOnTheGBufferSurfaceAndMarksSkyInvalid) {
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
TEST_P(ScreenProbeGpuTest, EveryPassRunsTimedAndSkyProbesAreSkipped) {
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

// Relative error of irradiance against pi L per surface pixel, for the furnace.
struct FurnaceErrors {
    std::vector<float> errors;
    float worst() const { return errors.empty() ? 0.0f : *std::max_element(errors.begin(), errors.end()); }
    float quantile(float q) const {
        std::vector<float> sorted = errors;
        std::sort(sorted.begin(), sorted.end());
        return sorted[std::min(sorted.size() - 1, size_t(q * float(sorted.size())))];
    }
    float mean() const {
        double sum = 0.0;
        for (float e : errors) {
            sum += e;
        }
        return float(sum / double(errors.size()));
    }
};

// The white furnace: every ray sees the same radiance L (the sky where it leaves the box, the
// voxel lighting filled with L where it hits a wall), so the irradiance at every surface pixel is
// pi L, after 40 frames of accumulation. Tolerance 0.5% per pixel and channel, 0.3% on average: the
// SH quadrature (0.04%) and the half-float targets (atlas, gather, result: 0.05% each). Measured on
// lavapipe: mean 0.06%, worst 0.14%. (A uniform environment gives the same irradiance for every
// normal, so this does not see the tile's interpolation error; octahedral_test measures that.)
TEST_P(ScreenProbeGpuTest, WhiteFurnaceGivesPiLAtEveryPixelAndStaysFinite) {
    LUMINA_REQUIRE_KERNELS();
    const glm::vec3 L(0.8f, 0.5f, 0.25f);
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), kSize, kSize);
    harness.setSky(L);
    harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, 1.0f); });
    const image::Image normal = [&] {
        harness.render();
        return harness.read(harness.renderer().gbuffer().normal);
    }();
    const int frames = 40;
    for (int frame = 1; frame < frames; ++frame) {
        harness.render();
    }
    const image::Image result = harness.read(harness.probes().irradiance());
    FurnaceErrors errors;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const image::Rgb e = result.rgbAt(x, y);
            ASSERT_TRUE(std::isfinite(e.r) && std::isfinite(e.g) && std::isfinite(e.b)) << x << "," << y;
            if (normal.at("A", x, y) == 0.0f) {
                continue;
            }
            EXPECT_EQ(result.at("A", x, y), float(frames)) << "frames accumulated at " << x << "," << y;
            for (int c = 0; c < 3; ++c) {
                errors.errors.push_back(std::abs((&e.r)[c] / (kPi * L[c]) - 1.0f));
            }
        }
    }
    ASSERT_GT(errors.errors.size(), size_t(kSize * kSize * 3 / 2));
    RecordProperty("mean_relative_error", std::to_string(errors.mean()));
    std::cout << "furnace: mean " << errors.mean() << ", 95% " << errors.quantile(0.95f) << ", 99% "
              << errors.quantile(0.99f) << ", worst " << errors.worst() << '\n';
    EXPECT_LT(errors.mean(), 0.003f);
    EXPECT_LT(errors.worst(), 0.005f);

    // The accumulated probe radiance is L wherever it has data: never above it.
    const auto history =
        harness.read<gpu::float4>(harness.probes().resources().history[harness.probes().current()]);
    const auto probes =
        harness.read<gpu::ScreenProbe>(harness.probes().resources().probes[harness.probes().current()]);
    for (size_t i = 0; i < history.size(); ++i) {
        if (probes[i / LUMINA_SP_PROBE_TEXELS].info.x != LUMINA_SP_PROBE_VALID || history[i].w <= 0.0f) {
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(history[i][c], L[c], 1e-5f * L[c] + 1e-3f * L[c]) << "texel " << i;
        }
    }
}

// Accumulation is a convex combination of its inputs: with every ray's radiance at most B (a sky
// and a voxel volume that change randomly each frame, never above B), the probe history and the
// screen result never exceed B (pi B for irradiance), through NaN and Inf frames of sky too.
TEST_P(ScreenProbeGpuTest, TemporalAccumulationNeverExceedsTheInputBound) {
    LUMINA_REQUIRE_KERNELS();
    const float B = 2.0f;
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 32, 32);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (int frame = 0; frame < 24; ++frame) {
        glm::vec3 sky(B * unit(rng), B * unit(rng), B * unit(rng));
        if (frame == 10) {
            sky = glm::vec3(nan, 1.0f, 1.0f);
        } else if (frame == 11) {
            sky = glm::vec3(inf, inf, 0.0f);
        }
        harness.setSky(sky);
        harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) {
            const float occupancy = 0.25f + 0.75f * unit(rng);
            return glm::vec4(B * unit(rng) * occupancy, B * unit(rng) * occupancy, B * unit(rng) * occupancy,
                             occupancy);
        });
        harness.render();
        const gi::ScreenProbeResources& r = harness.probes().resources();
        const uint32_t current = harness.probes().current();
        const auto probes = harness.read<gpu::ScreenProbe>(r.probes[current]);
        const auto history = harness.read<gpu::float4>(r.history[current]);
        for (size_t i = 0; i < history.size(); ++i) {
            if (probes[i / LUMINA_SP_PROBE_TEXELS].info.x != LUMINA_SP_PROBE_VALID) {
                continue;
            }
            for (int c = 0; c < 4; ++c) {
                ASSERT_TRUE(std::isfinite(history[i][c])) << "frame " << frame << " texel " << i;
            }
            for (int c = 0; c < 3; ++c) {
                // Radiance from half-float voxels: B to within half-float rounding.
                ASSERT_LE(history[i][c], B * (1.0f + 1e-3f)) << "frame " << frame << " texel " << i;
                ASSERT_GE(history[i][c], 0.0f) << "frame " << frame << " texel " << i;
            }
        }
        const image::Image screen = harness.read(harness.probes().irradiance());
        for (uint32_t y = 0; y < 32; ++y) {
            for (uint32_t x = 0; x < 32; ++x) {
                const image::Rgb e = screen.rgbAt(x, y);
                for (const float v : {e.r, e.g, e.b}) {
                    ASSERT_TRUE(std::isfinite(v)) << "frame " << frame << " pixel " << x << "," << y;
                    ASSERT_LE(v, kPi * B * 1.01f) << "frame " << frame << " pixel " << x << "," << y;
                }
            }
        }
    }
}

// Moving the camera a little keeps the screen history of surfaces that stay in view (their frame
// count goes on) and restarts where the view uncovers something new; resetHistory restarts all.
TEST_P(ScreenProbeGpuTest, ScreenHistoryFollowsTheCameraAndRestartsWhereDisoccluded) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.setSky(glm::vec3(0.5f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.5f, 0.5f, 0.5f, 1.0f); });
    for (int i = 0; i < 3; ++i) {
        harness.render();
    }
    scene::Camera moved = harness.scene().camera;
    moved.position -= moved.forward * 900.0f;
    moved.position += moved.right() * 60.0f;
    harness.setCamera(moved);
    harness.render();
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image frames = harness.read(harness.probes().irradiance());
    uint32_t kept = 0, restarted = 0, surface = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (normal.at("A", x, y) == 0.0f) {
                EXPECT_EQ(frames.at("A", x, y), 0.0f);
                continue;
            }
            ++surface;
            const float count = frames.at("A", x, y);
            kept += count == 4.0f;
            restarted += count == 1.0f;
            EXPECT_TRUE(count == 4.0f || count == 1.0f) << x << "," << y << ": " << count;
        }
    }
    EXPECT_GT(kept, surface * 8 / 10) << "most of the box stays in view";
    EXPECT_GT(restarted, 0u) << "the left edge of the box was off screen before";
    harness.probes().resetHistory();
    harness.render();
    const image::Image after = harness.read(harness.probes().irradiance());
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            EXPECT_EQ(after.at("A", x, y), normal.at("A", x, y) > 0.0f ? 1.0f : 0.0f) << x << "," << y;
        }
    }
}

// The lighting PDF: without history it is uniform in solid angle; from the second frame on it is
// (1 - floor) x luminance x solid angle of last frame's probe radiance, normalised, plus the floor
// spread uniformly. Walls are black here and the sky bright, so the table is far from uniform.
TEST_P(ScreenProbeGpuTest, LightingPdfFollowsLastFramesRadianceAboveAFloor) {
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
    uint32_t skewed = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        std::vector<float> mass(LUMINA_SP_PROBE_TEXELS, 0.0f);
        float massTotal = 0.0f, sum = 0.0f, lo = 1.0f, hi = 0.0f;
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            const gpu::float4 h = history[p * LUMINA_SP_PROBE_TEXELS + t];
            mass[t] = h.w > 0.0f ? gpu::luminance(gpu::float3(h)) * solid[t] : 0.0f;
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
}

// Probe radiance history: a static camera keeps it (weights follow W' = 0.9 W + 0.1 w exactly);
// after resetHistory nothing is kept (W' = 0.1 w); after a camera move each probe keeps it exactly
// when the old probe its position reprojects to lies on its plane, faces its way and is near.
TEST_P(ScreenProbeGpuTest, ProbeHistoryIsKeptOnTheSameSurfaceAndRejectedWhereProbesMoved) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.setSky(glm::vec3(1.0f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.5f, 0.5f, 0.5f, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const gi::ScreenProbeSettings& settings = harness.probes().settings();
    struct Frame {
        std::vector<gpu::ScreenProbe> probes;
        std::vector<gpu::float4> composite, history;
    };
    auto frame = [&] {
        harness.render();
        const uint32_t c = harness.probes().current();
        return Frame{harness.read<gpu::ScreenProbe>(r.probes[c]), harness.read<gpu::float4>(r.frameRadiance),
                     harness.read<gpu::float4>(r.history[c])};
    };
    // kept: W' = 0.9 W + 0.1 w for every texel; rejected: W' = 0.1 w.
    auto weightsFollow = [&](const Frame& now, uint32_t p, const std::vector<gpu::float4>* old,
                             uint32_t oldProbe) {
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            const float w = now.composite[p * LUMINA_SP_PROBE_TEXELS + t].w;
            const float before = old ? (*old)[oldProbe * LUMINA_SP_PROBE_TEXELS + t].w : 0.0f;
            const float expected =
                (1.0f - settings.probeHistoryBlend) * before + settings.probeHistoryBlend * w;
            if (std::abs(now.history[p * LUMINA_SP_PROBE_TEXELS + t].w - expected) >
                1e-5f * (1.0f + expected)) {
                return false;
            }
        }
        return true;
    };
    const Frame first = frame();
    Frame second = frame();
    uint32_t valid = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (second.probes[p].info.x == LUMINA_SP_PROBE_VALID) {
            ++valid;
            EXPECT_TRUE(weightsFollow(second, p, &first.history, p)) << "static camera, probe " << p;
        }
    }
    ASSERT_GT(valid, 0u);
    harness.probes().resetHistory();
    second = frame();
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (second.probes[p].info.x == LUMINA_SP_PROBE_VALID) {
            EXPECT_TRUE(weightsFollow(second, p, nullptr, 0)) << "after reset, probe " << p;
        }
    }
    // Move sideways by a third of a cell's world size at the box and up a little.
    scene::Camera moved = cornellWithSky().camera;
    const gpu::GpuCamera before = gi::makeGpuCamera(moved, kSize, kSize);
    moved.position += moved.right() * 13.0f + moved.up * 7.0f;
    harness.setCamera(moved);
    const Frame third = frame();
    uint32_t kept = 0, rejected = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        const gpu::ScreenProbe& probe = third.probes[p];
        if (probe.info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        // Where this probe's surface was on screen last frame, and the old probe there.
        const glm::vec4 world(glm::vec3(probe.positionAndDepth), 1.0f);
        const glm::vec4 clip(glm::dot(before.viewProjRows[0], world), glm::dot(before.viewProjRows[1], world),
                             glm::dot(before.viewProjRows[2], world),
                             glm::dot(before.viewProjRows[3], world));
        const glm::vec2 pixel =
            glm::vec2(0.5f + 0.5f * clip.x / clip.w, 0.5f - 0.5f * clip.y / clip.w) * float(kSize);
        bool matches = false;
        uint32_t oldIndex = 0;
        if (clip.w > 0.0f && pixel.x >= 0.0f && pixel.y >= 0.0f && pixel.x < kSize && pixel.y < kSize) {
            oldIndex = uint32_t(pixel.y) / 8 * r.gridWidth + uint32_t(pixel.x) / 8;
            const gpu::ScreenProbe& old = second.probes[oldIndex];
            const glm::vec3 offset = glm::vec3(old.positionAndDepth) - glm::vec3(probe.positionAndDepth);
            const float depth = probe.positionAndDepth.w;
            const float cell = 8.0f * 2.0f * before.positionAndTanHalfFovY.w * depth / float(kSize);
            matches =
                old.info.x == LUMINA_SP_PROBE_VALID &&
                std::abs(glm::dot(offset, glm::vec3(probe.normal))) <=
                    settings.historyPlaneTolerance * depth &&
                glm::dot(glm::vec3(old.normal), glm::vec3(probe.normal)) >= settings.historyNormalTolerance &&
                glm::length(offset) <= 1.5f * cell;
        }
        // Near the tolerances the GPU's rounding may decide either way: accept both there.
        const bool keptHere = weightsFollow(third, p, &second.history, oldIndex);
        const bool rejectedHere = weightsFollow(third, p, nullptr, 0);
        EXPECT_TRUE(matches ? keptHere : rejectedHere)
            << "probe " << p << (matches ? " should keep" : " should reject");
        kept += matches && keptHere;
        rejected += !matches && rejectedHere;
    }
    EXPECT_GT(kept, 0u);
    EXPECT_GT(rejected, 0u);
}

// Direction, end to end: the voxel lighting is red on the box's +x half (the red wall's side, on
// the image's left) and green on the -x half, the sky black. Floor, ceiling and back wall pixels
// face neither half, so they see more of the half they stand in: red exceeds green where the
// surface lies well inside the +x half and the other way round. A flipped ray direction, SH band
// or octahedral axis breaks this; the furnace cannot see any of those.
TEST_P(ScreenProbeGpuTest, IrradianceComesFromTheSideTheLightIsOn) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), kSize, kSize);
    const scene::Bounds box = harness.scene().worldBounds();
    const float centre = 0.5f * (box.min.x + box.max.x), width = box.max.x - box.min.x;
    const uint32_t dims = harness.voxelDims();
    const glm::vec3 lo = harness.voxelMin(), hi = harness.voxelMax();
    harness.fillVoxels([&](uint32_t x, uint32_t, uint32_t) {
        const float worldX = lo.x + (float(x) + 0.5f) / float(dims) * (hi.x - lo.x);
        return worldX > centre ? glm::vec4(1.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    });
    for (int i = 0; i < 8; ++i) {
        harness.render();
    }
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image position = harness.read(harness.renderer().gbuffer().position);
    const image::Image result = harness.read(harness.probes().irradiance());
    uint32_t checked = 0, right = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const image::Rgb n = normal.rgbAt(x, y);
            if (normal.at("A", x, y) == 0.0f || std::abs(n.r) > 0.2f) {
                continue; // sky, or a surface facing one of the halves (side walls, block sides)
            }
            const float offset = position.rgbAt(x, y).r - centre;
            if (std::abs(offset) < 0.25f * width) {
                continue;
            }
            const image::Rgb e = result.rgbAt(x, y);
            ASSERT_GT(e.r + e.g, 0.0f) << x << "," << y;
            ++checked;
            right += (offset > 0.0f) == (e.r > e.g);
        }
    }
    ASSERT_GT(checked, kSize * kSize / 8);
    EXPECT_GE(right, checked * 98 / 100) << right << " of " << checked;
}

// Every intermediate can be read back: the dump writes one EXR per buffer, and what it writes is
// what the buffers hold (history and the lighting PDF, texel for texel, probe (x, y) at tile (x, y)).
TEST_P(ScreenProbeGpuTest, DumpWritesEveryIntermediateAsItIs) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32);
    harness.setSky(glm::vec3(1.0f, 0.5f, 0.25f));
    harness.fillVoxels(
        [](uint32_t x, uint32_t, uint32_t) { return glm::vec4(0.1f * float(x), 0.2f, 0.3f, 1.0f); });
    harness.render();
    harness.render();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("lumina_screen_probe_dump_" + std::to_string(std::random_device{}()));
    const auto written = gi::dumpScreenProbeBuffers(device(), harness.probes(), dir);
    EXPECT_EQ(written.size(), 14u);
    for (const auto& path : written) {
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
    }
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const auto history = harness.read<gpu::float4>(r.history[harness.probes().current()]);
    const auto pdf = harness.read<float>(r.lightingPdf);
    const image::Image historyImage = image::readExr(dir / "screen_probes_history.exr");
    const image::Image pdfImage = image::readExr(dir / "screen_probes_lighting_pdf.exr");
    ASSERT_EQ(historyImage.width(), r.gridWidth * 8);
    ASSERT_EQ(historyImage.height(), r.gridHeight * 8);
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
    uint32_t compared = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            const uint32_t x = (p % r.gridWidth) * 8 + t % 8, y = (p / r.gridWidth) * 8 + t / 8;
            ASSERT_EQ(historyImage.at("G", x, y), history[p * 64 + t].y) << p << "," << t;
            ASSERT_EQ(historyImage.at("A", x, y), history[p * 64 + t].w) << p << "," << t;
            ASSERT_EQ(pdfImage.at("R", x, y), pdf[p * 64 + t]) << p << "," << t;
            ++compared;
        }
    }
    EXPECT_GT(compared, 0u);
    std::filesystem::remove_all(dir);
}

// The MIS directions on the GPU are the CPU reference's (probe_sampling_shared.h: the same
// low-discrepancy point warped through the same tables, read back), lie in the texel they name,
// and carry the balance-heuristic weight of both tables; over frames, the BRDF rays fill the
// texels in proportion to the cosine table.
TEST_P(ScreenProbeGpuTest, MisDirectionsAreTheTablesWarpedAndCarryTheirWeights) {
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
                const glm::vec2 u =
                    gpu::spSamplePoint(fromBrdf ? i : i - nb, fromBrdf ? nb : nl, frame, p, ray.info.y);
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
TEST_P(ScreenProbeGpuTest, AStrategyWithoutRaysSkipsItsTable) {
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
        const std::string reason =
            fraction == 0.0f ? "no BRDF rays (brdfRayFraction 0)" : "no lighting rays (brdfRayFraction 1)";
        EXPECT_EQ(std::count(passes.begin(), passes.end(), skippedPass), 0) << skippedPass;
        std::vector<gi::SkippedPass> ours; // the deferred renderer skips its sun shadow too
        std::copy_if(harness.skipped().begin(), harness.skipped().end(), std::back_inserter(ours),
                     [](const gi::SkippedPass& skip) { return skip.pass.rfind("screen probes: ", 0) == 0; });
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

// The outlier clamp: after the history settles at L, one frame of a sky 1000x brighter moves no
// texel above outlierClamp x L (without the clamp the sky texels would jump to about 100 L), and
// the next normal frame pulls them back down.
TEST_P(ScreenProbeGpuTest, OutlierClampLimitsASingleBrightFrame) {
    LUMINA_REQUIRE_KERNELS();
    const float L = 0.5f;
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32);
    harness.setSky(glm::vec3(L));
    harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, L, L, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    for (int i = 0; i < 10; ++i) {
        harness.render();
    }
    auto maxHistory = [&] {
        const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
        const auto history = harness.read<gpu::float4>(r.history[harness.probes().current()]);
        float most = 0.0f;
        for (size_t i = 0; i < history.size(); ++i) {
            if (probes[i / LUMINA_SP_PROBE_TEXELS].info.x == LUMINA_SP_PROBE_VALID) {
                most = std::max(most, history[i].x);
            }
        }
        return most;
    };
    EXPECT_NEAR(maxHistory(), L, 1e-4f);
    harness.setSky(glm::vec3(1000.0f * L));
    harness.render();
    const float clamp = harness.probes().settings().outlierClamp;
    const float afterSpike = maxHistory();
    EXPECT_GT(afterSpike, 1.01f * L) << "the bright frame counts, within the clamp";
    EXPECT_LE(afterSpike, clamp * L * (1.0f + 1e-4f));
    harness.setSky(glm::vec3(L));
    harness.render();
    EXPECT_LT(maxHistory(), afterSpike);
}

// Stability: 300 frames of a camera that drifts and turns, with a sky that flickers
// over four orders of magnitude; the result stays finite and within pi x the brightest input.
TEST_P(ScreenProbeGpuTest, LongRunWithAMovingCameraStaysFiniteAndBounded) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 24, 16);
    harness.fillVoxels([](uint32_t x, uint32_t y, uint32_t z) {
        return glm::vec4(0.1f * float(x % 3), 0.2f * float(y % 2), 0.05f * float(z % 5), 1.0f);
    });
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const scene::Camera start = cornellWithSky().camera;
    float brightest = 0.4f; // the voxel volume's largest value
    for (int frame = 0; frame < 300; ++frame) {
        const float sky = std::pow(10.0f, 4.0f * unit(rng) - 2.0f);
        brightest = std::max(brightest, sky);
        harness.setSky(glm::vec3(sky));
        scene::Camera camera = start;
        const float t = 0.05f * float(frame);
        camera.position += camera.right() * (150.0f * std::sin(t)) + camera.up * (80.0f * std::sin(0.7f * t));
        camera.forward = glm::normalize(camera.forward + camera.right() * (0.2f * std::cos(t)));
        harness.setCamera(camera);
        harness.render();
        if (frame % 50 == 49) {
            const image::Image result = harness.read(harness.probes().irradiance());
            for (uint32_t y = 0; y < 16; ++y) {
                for (uint32_t x = 0; x < 24; ++x) {
                    const image::Rgb e = result.rgbAt(x, y);
                    for (const float v : {e.r, e.g, e.b}) {
                        ASSERT_TRUE(std::isfinite(v)) << "frame " << frame << " pixel " << x << "," << y;
                        ASSERT_GE(v, 0.0f) << "frame " << frame;
                        ASSERT_LE(v, kPi * brightest * 1.01f) << "frame " << frame;
                    }
                }
            }
        }
    }
}

// Not a test: GPU time per pass (median of 10 frames after 3), for docs/screen_probes.md. Run with
// --gtest_also_run_disabled_tests --gtest_filter='*PrintPassTimes*'; LUMINA_SP_TIMING_SIZE=WxH.
TEST_P(ScreenProbeGpuTest, DISABLED_PrintPassTimes) {
    LUMINA_REQUIRE_KERNELS();
    uint32_t width = 320, height = 180;
    if (const char* size = std::getenv("LUMINA_SP_TIMING_SIZE")) {
        std::sscanf(size, "%ux%u", &width, &height);
    }
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), width, height, {},
                               32);
    harness.setSky(glm::vec3(0.5f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.5f, 0.5f, 0.5f, 1.0f); });
    std::map<std::string, std::vector<double>> times;
    for (int frame = 0; frame < 13; ++frame) {
        harness.render();
        for (const rhi::TimerResult& timer : harness.timings()) {
            if (frame >= 3 && timer.name.rfind("screen probes: ", 0) == 0) {
                times[timer.name].push_back(timer.milliseconds);
            }
        }
    }
    std::cout << device().adapter().name << ", " << width << "x" << height << '\n';
    double total = 0.0;
    for (auto& [name, ms] : times) {
        std::sort(ms.begin(), ms.end());
        total += ms[ms.size() / 2];
        std::cout << "| " << name << " | " << ms[ms.size() / 2] << " |\n";
    }
    std::cout << "| total | " << total << " |\n";
}

TEST_P(ScreenProbeGpuTest, BadInputsAreRefusedByName) {
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

LUMINA_INSTANTIATE_GPU_TEST(ScreenProbeGpuTest);

} // namespace
} // namespace lumina::test
