// Scenes from real files (docs/scenes.md, "The default light"): a glTF that brings no light
// gets the default sun and sky and renders lit; LoadOptions::defaultLight = false
// (`--no-default-light`) keeps it black; and every glTF 2.0 model of Debian's assimp-testmodels
// that loads and draws triangles renders lit with default settings.
//
// The models are rendered with the direct technique at 32x32: lumen would build mesh SDFs and
// run the surface cache for each of the ~40 models, minutes apiece on lavapipe, and the default
// sun alone decides whether a model is lit; tests/frame/frame_accuracy_gpu_test.cpp and the
// screen-probe tests cover what lumen adds under a sky.
#include "gi/scene/default_light.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

namespace fs = std::filesystem;

const fs::path kAssimpGltf2 = "/usr/share/assimp/models/glTF2";
// A plain textured box without lights or emission (assimp-testmodels).
const fs::path kBox = kAssimpGltf2 / "BoxTextured-glTF" / "BoxTextured.gltf";
// A surface pixel counts as lit above this luminance (display-referred 0.01 is far below any
// surface the default sun of irradiance 3 reaches, far above rounding in a black frame).
constexpr float kLitLuminance = 0.01f;

struct SurfaceLight {
    uint32_t surfacePixels = 0; // pixels where the GBuffer has a surface
    uint32_t litPixels = 0;     // those brighter than kLitLuminance
    double meanLuminance = 0.0; // over the surface pixels
    float maxRadiance = 0.0f;   // any channel of any pixel, the background included
};

// The direct light (what the direct technique shows) over the GBuffer's surface pixels.
SurfaceLight measureSurfaceLight(FrameHarness& h) {
    const image::Image normal = h.read(h.renderer().deferred().gbuffer().normal);
    const image::Image direct = h.direct();
    const std::span<const float> a = normal.channel("A");
    const std::span<const float> r = direct.channel("R"), g = direct.channel("G"), b = direct.channel("B");
    SurfaceLight out;
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        out.maxRadiance = std::max({out.maxRadiance, r[i], g[i], b[i]});
        if (a[i] <= 0.0f) {
            continue;
        }
        const float luminance = 0.2126f * r[i] + 0.7152f * g[i] + 0.0722f * b[i];
        ++out.surfacePixels;
        out.litPixels += luminance > kLitLuminance ? 1u : 0u;
        sum += luminance;
    }
    out.meanLuminance = out.surfacePixels ? sum / out.surfacePixels : 0.0;
    return out;
}

SurfaceLight renderDirect(FrameHarness&& h) {
    h.render();
    return measureSurfaceLight(h);
}

class RealSceneGpu : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (!fs::is_directory(kAssimpGltf2)) {
            GTEST_SKIP() << "assimp-testmodels is not installed (" << kAssimpGltf2 << ")";
        }
    }
    FrameHarness harness(scene::Scene scene, uint32_t size) {
        return FrameHarness(device(), shaders(), std::move(scene),
                            {.width = size, .height = size, .technique = gi::GiTechnique::Direct});
    }
};

TEST_P(RealSceneGpu, GltfWithoutLightsGetsTheDefaultLightAndRendersLit) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene lit = scene::loadScene(kBox.string());
    ASSERT_TRUE(lit.defaultLight);
    const SurfaceLight light = renderDirect(harness(lit, 64));
    ASSERT_GT(light.surfacePixels, 64u * 64u / 10) << "the box fills part of the view";
    EXPECT_GT(light.meanLuminance, 0.1) << "the default sun lights the faces the camera sees";
    EXPECT_GT(light.litPixels, light.surfacePixels / 2);
}

TEST_P(RealSceneGpu, NoDefaultLightKeepsItBlack) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene dark = scene::loadScene(kBox.string(), {.defaultLight = false});
    ASSERT_FALSE(dark.defaultLight);
    ASSERT_FALSE(scene::sceneHasLight(dark));
    const SurfaceLight light = renderDirect(harness(dark, 64));
    ASSERT_GT(light.surfacePixels, 0u);
    EXPECT_EQ(light.maxRadiance, 0.0f) << "no light, no sky: every pixel black";
}

// Every .gltf and .glb under assimp-testmodels' glTF2 folder: those that load and draw
// triangles must render with some surface lit. Those that fail to load (the package's
// deliberately broken files, unsupported extensions) are listed, not failed:
// tests/scene/assimp_models_test.cpp checks they fail cleanly.
TEST_P(RealSceneGpu, EveryLoadableAssimpGltfRendersLit) {
    LUMINA_REQUIRE_KERNELS();
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kAssimpGltf2)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb")) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    uint32_t rendered = 0;
    std::string skipped;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        scene::Scene loaded;
        try {
            loaded = scene::loadScene(file.string());
        } catch (const scene::SceneError& error) {
            skipped += std::string("\n  ") + error.what();
            continue;
        }
        const SurfaceLight light = renderDirect(harness(std::move(loaded), 32));
        ++rendered;
        EXPECT_GT(light.surfacePixels, 0u) << "the model is in view";
        EXPECT_GT(light.litPixels, 0u)
            << "some surface is lit (mean luminance " << light.meanLuminance << ")";
    }
    std::printf("rendered %u of %zu glTF files; skipped (failed to load):%s\n", rendered, files.size(),
                skipped.c_str());
    EXPECT_GE(rendered, 20u) << "most of the package's models load";
}

LUMINA_INSTANTIATE_GPU_TEST(RealSceneGpu);

} // namespace
} // namespace lumina::test
