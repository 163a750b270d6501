// The gather's result on the GPU: the white furnace, where light comes from, the dump of every
// intermediate, and a printout of pass times.
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
#include <string>

namespace lumina::test {
namespace {

using ScreenGatherGpuTest = GpuTest;

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
TEST_P(ScreenGatherGpuTest, WhiteFurnaceGivesPiLAtEveryPixelAndStaysFinite) {
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

// Direction, end to end: the voxel lighting is red on the box's +x half (the red wall's side, on
// the image's left) and green on the -x half, the sky black. Floor, ceiling and back wall pixels
// face neither half, so they see more of the half they stand in: red exceeds green where the
// surface lies well inside the +x half and the other way round. A flipped ray direction, SH band
// or octahedral axis breaks this; the furnace cannot see any of those.
TEST_P(ScreenGatherGpuTest, IrradianceComesFromTheSideTheLightIsOn) {
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
TEST_P(ScreenGatherGpuTest, DumpWritesEveryIntermediateAsItIs) {
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
    EXPECT_EQ(written.size(), 15u);
    for (const auto& path : written) {
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
    }
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const auto history = harness.read<gpu::float4>(r.history[harness.probes().current()]);
    const auto pdf = harness.read<float>(r.lightingPdf);
    const image::Image historyImage = image::readExr(dir / "screen_probes_history.exr");
    const image::Image pdfImage = image::readExr(dir / "screen_probes_lighting_pdf.exr");
    ASSERT_EQ(historyImage.width(), r.gridWidth * 8);
    ASSERT_EQ(historyImage.height(), r.probeRows() * 8); // the uniform grid's rows, then the adaptive ones
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

// Not a test: GPU time per pass (median of 10 frames after 3), for docs/screen_probes.md. Run with
// --gtest_also_run_disabled_tests --gtest_filter='*PrintPassTimes*'; LUMINA_SP_TIMING_SIZE=WxH;
// LUMINA_SP_TIMING_NEAR_FIELD=D adds a surface cache and traces the near field up to D (world
// units; "default": the setting's default), else there is no near field.
TEST_P(ScreenGatherGpuTest, DISABLED_PrintPassTimes) {
    LUMINA_REQUIRE_KERNELS();
    uint32_t width = 320, height = 180;
    if (const char* size = std::getenv("LUMINA_SP_TIMING_SIZE")) {
        std::sscanf(size, "%ux%u", &width, &height);
    }
    gi::ScreenProbeSettings settings;
    const char* nearField = std::getenv("LUMINA_SP_TIMING_NEAR_FIELD");
    if (nearField && std::string(nearField) != "default") {
        settings.nearFieldDistance = std::stof(nearField);
    }
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), width, height,
                               settings, 32);
    if (nearField) {
        harness.addSurfaceCache(cornellCacheSettings());
    }
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
    const gpu::SdfSceneInfo grid = harness.sdf().sceneInfo();
    const float diagonal = glm::length(grid.globalMax - grid.globalMin);
    const float near =
        settings.nearFieldDistance.value_or(gi::ScreenProbeSettings::kNearFieldGridFraction * diagonal);
    std::cout << device().adapter().name << ", " << width << "x" << height << ", near field "
              << (nearField ? near : 0.0f) << " (global SDF diagonal " << diagonal << ")\n";
    double total = 0.0;
    for (auto& [name, ms] : times) {
        std::sort(ms.begin(), ms.end());
        total += ms[ms.size() / 2];
        std::cout << "| " << name << " | " << ms[ms.size() / 2] << " |\n";
    }
    std::cout << "| total | " << total << " |\n";
}

LUMINA_INSTANTIATE_GPU_TEST(ScreenGatherGpuTest);

} // namespace
} // namespace lumina::test
