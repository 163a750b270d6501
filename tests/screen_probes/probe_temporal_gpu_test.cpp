// Temporal stability on the GPU: the bound of probe accumulation with NaN and Inf injected, the
// outlier clamp, probe and screen history across camera motion and cuts, a long run.
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

using ProbeTemporalGpuTest = GpuTest;

// Accumulation is a convex combination of its inputs: with every ray's radiance at most B (a sky
// and a voxel volume that change randomly each frame, never above B), the probe history and the
// screen result never exceed B (pi B for irradiance), through NaN and Inf frames of sky too.
TEST_P(ProbeTemporalGpuTest, TemporalAccumulationNeverExceedsTheInputBound) {
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

// The brightest red radiance among the valid probes' history texels.
float brightestHistoryTexel(ScreenProbeHarness& harness) {
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
    const auto history = harness.read<gpu::float4>(r.history[harness.probes().current()]);
    float most = 0.0f;
    for (size_t i = 0; i < history.size(); ++i) {
        if (probes[i / LUMINA_SP_PROBE_TEXELS].info.x == LUMINA_SP_PROBE_VALID) {
            most = std::max(most, history[i].x);
        }
    }
    return most;
}

// The outlier clamp: after the history settles at L, one frame of a sky 1000x brighter moves no
// texel above outlierClamp x L (without the clamp the sky texels would jump to about 100 L), and
// the next normal frame pulls them back down.
TEST_P(ProbeTemporalGpuTest, OutlierClampLimitsASingleBrightFrame) {
    LUMINA_REQUIRE_KERNELS();
    const float L = 0.5f;
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32);
    harness.setSky(glm::vec3(L));
    harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, L, L, 1.0f); });
    for (int i = 0; i < 10; ++i) {
        harness.render();
    }
    EXPECT_NEAR(brightestHistoryTexel(harness), L, 1e-4f);
    harness.setSky(glm::vec3(1000.0f * L));
    harness.render();
    const float clamp = harness.probes().settings().outlierClamp;
    const float afterSpike = brightestHistoryTexel(harness);
    EXPECT_GT(afterSpike, 1.01f * L) << "the bright frame counts, within the clamp";
    EXPECT_LE(afterSpike, clamp * L * (1.0f + 1e-4f));
    harness.setSky(glm::vec3(L));
    harness.render();
    EXPECT_LT(brightestHistoryTexel(harness), afterSpike);
}

// A texel averages k = rays / texels rays, so one bright ray moves it by 1/k of its excess; the
// clamp's factor, 1 + (outlierClamp - 1) / k, bounds that one ray the same at every ray count.
// With the new frame taking all the weight (probeHistoryBlend 1), a frame of a sky 1000x brighter
// leaves the brightest texel exactly at the factor x L: a fixed factor would read outlierClamp x L
// at 128 and 256 rays.
TEST_P(ProbeTemporalGpuTest, OutlierClampBoundsOneRayWhateverTheRaysATexel) {
    LUMINA_REQUIRE_KERNELS();
    const float L = 0.5f;
    for (const uint32_t rays : {32u, 64u, 128u, 256u}) {
        gi::ScreenProbeSettings settings;
        settings.raysPerProbe = rays;
        settings.probeHistoryBlend = 1.0f;
        ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32, settings);
        harness.setSky(glm::vec3(L));
        harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, L, L, 1.0f); });
        for (int i = 0; i < 4; ++i) {
            harness.render();
        }
        ASSERT_NEAR(brightestHistoryTexel(harness), L, 1e-4f) << rays << " rays";
        harness.setSky(glm::vec3(1000.0f * L));
        harness.render();
        const float raysPerTexel = std::max(float(rays) / float(LUMINA_SP_PROBE_TEXELS), 1.0f);
        const float factor = 1.0f + (settings.outlierClamp - 1.0f) / raysPerTexel;
        EXPECT_NEAR(brightestHistoryTexel(harness), factor * L, 1e-3f * factor * L) << rays << " rays";
    }
}

// The clamp must not make the history remember where it started. A sky that flickers to 50 L one
// frame in four reads between L and 50 L in every sky texel; two runs that settled on L and on 50 L
// and then see the same flicker for 300 frames must read the same. The rays are drawn from the BRDF
// alone, which does not read the history, so that both runs trace the same rays. Clamped against
// the texel's own history (a ceiling that rises only with what it lets in), sky texels stayed up to
// 40 % apart for good, and the probes' mean radiance read 0.73 and 0.76 where the unclamped one
// reads 1.03; against the unclamped means the two runs agree to rounding (measured on lavapipe).
TEST_P(ProbeTemporalGpuTest, TheOutlierClampForgetsWhereTheHistoryStarted) {
    LUMINA_REQUIRE_KERNELS();
    const float L = 0.5f, bright = 50.0f * L;
    std::vector<std::vector<gpu::float4>> histories;
    std::vector<gpu::ScreenProbe> probes;
    for (const float start : {L, bright}) {
        gi::ScreenProbeSettings settings;
        settings.brdfRayFraction = 1.0f;
        ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), 32, 32, settings);
        harness.fillVoxels([&](uint32_t, uint32_t, uint32_t) { return glm::vec4(L, L, L, 1.0f); });
        harness.setSky(glm::vec3(start));
        for (int i = 0; i < 40; ++i) {
            harness.render();
        }
        for (int frame = 0; frame < 300; ++frame) {
            harness.setSky(glm::vec3(frame % 4 == 0 ? bright : L));
            harness.render();
        }
        const gi::ScreenProbeResources& r = harness.probes().resources();
        probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
        histories.push_back(harness.read<gpu::float4>(r.history[harness.probes().current()]));
    }
    float worst = 0.0f;
    size_t skyTexels = 0;
    for (size_t i = 0; i < histories[0].size(); ++i) {
        if (probes[i / LUMINA_SP_PROBE_TEXELS].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        const float a = histories[0][i].x, b = histories[1][i].x;
        skyTexels += a > 1.5f * L ? 1 : 0;
        worst = std::max(worst, std::abs(a - b) / std::max(a, L));
    }
    ASSERT_GT(skyTexels, 0u) << "no texel sees the flickering sky";
    EXPECT_LT(worst, 1e-3f) << "history texels still differ by this share after 300 frames";
}

// Probe radiance history: a static camera keeps it (weights follow W' = 0.9 W + 0.1 w exactly);
// after resetHistory nothing is kept (W' = 0.1 w); after a camera move each probe keeps it exactly
// when the old probe its position reprojects to lies on its plane, faces its way and is near.
TEST_P(ProbeTemporalGpuTest, ProbeHistoryIsKeptOnTheSameSurfaceAndRejectedWhereProbesMoved) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), cornellWithSky(), kSize, kSize);
    harness.setSky(glm::vec3(1.0f));
    harness.fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.5f, 0.5f, 0.5f, 1.0f); });
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const gi::ScreenProbeSettings& settings = harness.probes().settings();
    struct Frame {
        std::vector<gpu::ScreenProbe> probes;
        std::vector<gpu::float4> composite, history;
        std::vector<uint32_t> adaptiveIndex;
    };
    auto frame = [&] {
        harness.render();
        const uint32_t c = harness.probes().current();
        return Frame{harness.read<gpu::ScreenProbe>(r.probes[c]), harness.read<gpu::float4>(r.frameRadiance),
                     harness.read<gpu::float4>(r.history[c]), harness.read<uint32_t>(r.adaptiveIndex[c])};
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
    uint32_t valid = 0, adaptive = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (second.probes[p].info.x == LUMINA_SP_PROBE_VALID) {
            ++valid;
            adaptive += p >= r.uniformProbeCount;
            const std::optional<uint32_t> old =
                sameProbeLastFrame(first.probes, second.probes, p, r.uniformProbeCount);
            ASSERT_TRUE(old.has_value()) << "probe " << p << " was not placed last frame";
            EXPECT_TRUE(weightsFollow(second, p, &first.history, *old)) << "static camera, probe " << p;
        }
    }
    ASSERT_GT(valid, 0u);
    ASSERT_GT(adaptive, 0u) << "adaptive probes on the box's silhouette";
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
        // Whether the old probe in `slot` saw this probe's surface.
        const auto sawIt = [&](uint32_t slot) {
            const gpu::ScreenProbe& old = second.probes[slot];
            const glm::vec3 offset = glm::vec3(old.positionAndDepth) - glm::vec3(probe.positionAndDepth);
            const float depth = probe.positionAndDepth.w;
            const float cell = 8.0f * 2.0f * before.tanHalfFovY * depth / float(kSize);
            return old.info.x == LUMINA_SP_PROBE_VALID &&
                   std::abs(glm::dot(offset, glm::vec3(probe.normal))) <=
                       settings.historyPlaneTolerance * depth &&
                   glm::dot(glm::vec3(old.normal), glm::vec3(probe.normal)) >=
                       settings.historyNormalTolerance &&
                   glm::length(offset) <= LUMINA_SP_HISTORY_MAX_CELLS * cell;
        };
        bool matches = false;
        uint32_t oldIndex = 0;
        if (clip.w > 0.0f && pixel.x >= 0.0f && pixel.y >= 0.0f && pixel.x < kSize && pixel.y < kSize) {
            // A uniform probe looks first in the old uniform cell there, an adaptive one first in the
            // old adaptive tile there; each then in the other.
            const uint32_t uniformSlot = uint32_t(pixel.y) / 8 * r.gridWidth + uint32_t(pixel.x) / 8;
            const uint32_t tile = uint32_t(pixel.y) / r.adaptiveSpacing * r.adaptiveWidth +
                                  uint32_t(pixel.x) / r.adaptiveSpacing;
            const uint32_t adaptiveSlot = second.adaptiveIndex[tile];
            std::vector<uint32_t> candidates = {uniformSlot};
            if (adaptiveSlot != LUMINA_SP_NO_ADAPTIVE_PROBE) {
                candidates.insert(p >= r.uniformProbeCount ? candidates.begin() : candidates.end(),
                                  adaptiveSlot);
            }
            for (const uint32_t slot : candidates) {
                if (!matches && sawIt(slot)) {
                    matches = true;
                    oldIndex = slot;
                }
            }
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

// Moving the camera a little keeps the screen history of surfaces that stay in view (their frame
// count goes on) and restarts where the view uncovers something new; resetHistory restarts all.
TEST_P(ProbeTemporalGpuTest, ScreenHistoryFollowsTheCameraAndRestartsWhereDisoccluded) {
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

// Stability: 300 frames of a camera that drifts and turns, with a sky that flickers
// over four orders of magnitude; the result stays finite and within pi x the brightest input.
TEST_P(ProbeTemporalGpuTest, LongRunWithAMovingCameraStaysFiniteAndBounded) {
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

LUMINA_INSTANTIATE_GPU_TEST(ProbeTemporalGpuTest);

} // namespace
} // namespace lumina::test
