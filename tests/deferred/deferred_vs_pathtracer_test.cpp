// The deferred renderer's direct-only frame against the path tracer's direct-light AOV on the
// same scene, camera, lights and pixel centres (no jitter): relMSE <= 0.01 away from shadow
// edges, where shadow-map filtering and bias legitimately differ from the path tracer's exact
// shadow rays.
#include "gi/measure/metrics.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/pathtracer/path_tracer_scene.h"
#include "gi/scene/scene_loader.h"
#include "tests/deferred/deferred_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cmath>

namespace lumina::test {
namespace {

using DeferredVsPathTracerTest = GpuTest;

constexpr uint32_t kSize = 64;
// Pixels within this many pixels of a shadow edge are left out of the comparison.
constexpr int kEdgeRadius = 2;
constexpr double kMaxRelMse = 0.01;
// No visibility where the light does not reach the surface anyway (or there is no surface).
constexpr float kNoVisibility = -1.0f;

// The path tracer's shadowing at each pixel: the direct light it found over what the shared
// light model delivers there unshadowed (position, normal and albedo from the GBuffer).
std::vector<float> referenceVisibility(DeferredHarness& harness, const image::Image& reference) {
    const GBufferImages gbuffer = harness.readGBuffer();
    std::vector<float> visibility(size_t(kSize) * kSize, kNoVisibility);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (gbuffer.normal.at("A", x, y) == 0.0f) {
                continue;
            }
            const Unshadowed expected = unshadowed(harness.renderer().lights(), gbuffer, x, y);
            const float lit = glm::dot(expected.reflected, gpu::float3(1.0f));
            if (lit > 1e-6f) {
                const float arrived = glm::dot(rgbAt(reference, x, y) - expected.emission, gpu::float3(1.0f));
                visibility[size_t(y) * kSize + x] = arrived / lit;
            }
        }
    }
    return visibility;
}

// True for pixels farther than kEdgeRadius from any shadow edge: a pixel in partial shadow, or
// next to one whose visibility differs by more than half.
std::vector<bool> awayFromShadowEdges(const std::vector<float>& visibility) {
    const int n = int(kSize);
    auto at = [&](int x, int y) { return visibility[size_t(y) * n + x]; };
    std::vector<bool> edge(visibility.size(), false);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const float v = at(x, y);
            if (v == kNoVisibility) {
                continue;
            }
            if (v > 0.02f && v < 0.98f) {
                edge[size_t(y) * n + x] = true;
            }
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx < n && y + dy < n && at(x + dx, y + dy) != kNoVisibility &&
                    std::abs(at(x + dx, y + dy) - v) > 0.5f) {
                    edge[size_t(y) * n + x] = edge[size_t(y + dy) * n + x + dx] = true;
                }
            }
        }
    }
    std::vector<bool> keep(visibility.size(), true);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            for (int j = std::max(0, y - kEdgeRadius); j <= std::min(n - 1, y + kEdgeRadius); ++j) {
                for (int i = std::max(0, x - kEdgeRadius); i <= std::min(n - 1, x + kEdgeRadius); ++i) {
                    keep[size_t(y) * n + x] = keep[size_t(y) * n + x] && !edge[size_t(j) * n + i];
                }
            }
        }
    }
    return keep;
}

TEST_P(DeferredVsPathTracerTest, CornellBoxPointDirectLightMatchesAwayFromShadowEdges) {
    const scene::Scene scene = scene::loadScene("cornell_box_point");
    gi::PathTracerScene traced(device(), scene);
    gi::PathTracer tracer(device(), traced, scene,
                          {.width = kSize, .height = kSize, .maxBounces = 1, .jitter = false, .aovs = true});
    {
        gi::PipelineCache pipelines(device(), shaders());
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        gi::FrameContext frame(pipelines, *list, 0);
        // A point light and no emitters: next-event estimation at the pixel centre is exact,
        // so a few samples settle every pixel.
        tracer.recordSamples(frame, 4);
        list->end();
        submitAndWait(*list);
    }
    const gi::PathTracerResult result = tracer.readResult();
    image::Image reference = image::Image::rgb(kSize, kSize);
    for (const char* c : {"R", "G", "B"}) {
        std::ranges::copy(result.image.channel(std::string("direct.") + c), reference.channel(c).begin());
    }

    DeferredHarness harness(device(), shaders(), scene, kSize, kSize, &traced.gpuScene());
    harness.render();
    const image::Image direct = harness.read(harness.renderer().direct());

    // relMSE as docs/measurement.md defines it, over the pixels away from edges.
    const std::vector<bool> keep = awayFromShadowEdges(referenceVisibility(harness, reference));
    double sum = 0.0;
    uint32_t kept = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (!keep[size_t(y) * kSize + x]) {
                continue;
            }
            ++kept;
            for (const char* c : {"R", "G", "B"}) {
                const double r = reference.at(c, x, y), t = direct.at(c, x, y);
                sum += (t - r) * (t - r) / (r * r + measure::kRelMseEpsilon);
            }
        }
    }
    const double relMse = sum / (3.0 * std::max(kept, 1u));
    EXPECT_GT(kept, kSize * kSize * 7 / 10) << "too much of the image counted as shadow edges";
    EXPECT_LE(relMse, kMaxRelMse) << kept << " of " << kSize * kSize << " pixels compared";
    std::cout << "deferred vs path tracer (cornell_box_point, direct light, " << kSize << "x" << kSize
              << "): relMSE " << relMse << " over " << kept << " of " << kSize * kSize
              << " pixels away from edges; whole image " << measure::relMse(reference, direct) << '\n';
}

LUMINA_INSTANTIATE_GPU_TEST(DeferredVsPathTracerTest);

} // namespace
} // namespace lumina::test
