// The surface cache's multi-bounce energy in furnace scenes (gi/scene/generators/furnace.cpp: a
// closed room and a block, every surface of albedo rho emitting Le = 1): the exact outgoing
// radiance is Le / (1 - rho) everywhere. Combine, voxel lighting and radiosity run until the
// schedule declares convergence; the final layer must then hold the analytic value within 2 %
// (every texel for rho <= 0.95; at rho = 0.99 the mean within 1 %, every texel within 1.5 %), and
// the radiosity's rays must find a surface (RadiosityRayStats).
#include "gi/scene/scene_loader.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class SurfaceCacheFurnaceGpu : public GpuTest {};

// The 0.8 m block at 62 texels per metre takes 64 texels a side, the 4 m walls the cap of 128
// (the resolutions of the 64-texel tiles this test was written with). With the block at 32
// texels, floor texels along the block's base read 10-12.5% low (mean unchanged): coarse cards
// darken contact edges (docs/surface_cache.md, level of detail).
SurfaceCacheSettings furnaceSettings() {
    SurfaceCacheSettings s;
    s.atlasSize = 512;
    s.texelsPerUnit = 62.0f;
    s.maxCardTexels = 128;
    return s;
}

struct FurnaceResult {
    uint32_t updates = 0;
    uint32_t texels = 0;
    float meanRelError = 0.0f; // signed, (final - exact) / exact
    float maxAbsRelError = 0.0f;
    float maxValue = 0.0f;
    bool finite = true;
    gpu::RadiosityRayStats rays{};
};

// Texels nothing can see: the block's face lying on the floor, and the room's floor under the
// block (within a centimetre of the block's box, in its frame). Every other captured texel counts.
bool hidden(const scene::Scene& scene, const SurfaceCards& cards, uint32_t card, glm::vec3 world) {
    if (cards.instanceOf(card) == 1) {
        return cards.cards()[card].info.z == LUMINA_CARD_AXIS_NEG_Y;
    }
    const glm::vec3 local = glm::vec3(glm::inverse(scene.instances[1].transform) * glm::vec4(world, 1.0f));
    constexpr float kHalfBlock = 0.4f + 0.01f;
    return glm::all(glm::lessThanEqual(glm::abs(local), glm::vec3(kHalfBlock)));
}

FurnaceResult runFurnace(rhi::IDevice& device, rhi::ShaderLibrary& shaders, const std::string& name,
                         float rho) {
    SurfaceCacheHarness h(device, shaders, scene::loadScene(name), furnaceSettings());
    FurnaceResult result;
    // Until radiosity is converged, then one more update: combine turns the last bounce's
    // irradiance into radiance.
    const uint32_t limit = h.cache.radiositySchedule().requiredUpdates() + 4;
    while (result.updates < limit) {
        const auto skipped = h.update();
        ++result.updates;
        if (!skipReason(skipped, RadiosityPass::kTracePassName).empty() &&
            skipReason(skipped, SurfaceCacheCombinePass::kPassName).empty()) {
            break;
        }
    }
    const float exact = 1.0f / (1.0f - rho);
    const std::vector<glm::vec4> final = h.cache.readLayer(AtlasLayer::FinalLighting);
    const std::vector<glm::vec4> normal = h.cache.readLayer(AtlasLayer::Normal);
    const uint32_t size = h.cache.atlas().size();
    const std::vector<glm::vec3> world = atlasWorldPositions(h.device_, h.cache);
    double sum = 0.0;
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const size_t i = size_t(y) * size + x;
            const uint32_t card = atlasTexelOwner(h.cache, x, y);
            if (normal[i].a == 0.0f || card == kNoOwner || hidden(h.scene, h.cache.cards(), card, world[i])) {
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                result.finite = result.finite && std::isfinite(final[i][c]);
                result.maxValue = std::max(result.maxValue, final[i][c]);
            }
            const float rel = (final[i].r - exact) / exact;
            result.maxAbsRelError = std::max(result.maxAbsRelError, std::abs(rel));
            sum += rel;
            ++result.texels;
        }
    }
    result.meanRelError = result.texels ? float(sum / result.texels) : 0.0f;
    std::printf(
        "%s: %u updates, %u texels, mean rel error %+.4f, max |rel error| %.4f, max %.4f (exact %.4f)\n",
        name.c_str(), result.updates, result.texels, result.meanRelError, result.maxAbsRelError,
        result.maxValue, exact);
    h.timings.print(std::cout);
    result.rays = h.cache.radiosity().readRayStats(h.device_);
    std::printf("  rays %u: left the scene %u, out of steps %u, hits %u (%u by the gradient's side, %u "
                "found no surface)\n",
                result.rays.rays, result.rays.leftScene, result.rays.outOfSteps, result.rays.hits,
                result.rays.gradientSide, result.rays.unlitHits);
    return result;
}

// A closed room: every ray hits a surface and reads its light. A hit that finds no covered voxel
// face reads zero, a loss that grows as 1 / (1 - rho): 0.021 % of the rays did when the lookups
// began turning the normal to face the ray, and cost furnace_0.99 2.7 % (docs/gi.md, energy);
// 0.0007 % since the SDF gradient's side answers where the turned normal finds nothing.
void expectRaysFindSurfaces(const FurnaceResult& r) {
    EXPECT_LT(double(r.rays.outOfSteps), 1e-6 * double(r.rays.rays)); // 23 of 78 M at rho = 0.99
    EXPECT_GT(r.rays.hits, 0u);
    EXPECT_LT(double(r.rays.unlitHits), 2e-5 * double(r.rays.hits));
}

void expectConverged(const FurnaceResult& r) {
    expectRaysFindSurfaces(r);
    EXPECT_TRUE(r.finite);
    EXPECT_GT(r.texels, 6u * 60u * 60u);
    EXPECT_LT(r.maxAbsRelError, 0.02f);
}

TEST_P(SurfaceCacheFurnaceGpu, Rho050ConvergesToTheAnalyticRadiance) {
    LUMINA_REQUIRE_KERNELS();
    expectConverged(runFurnace(device(), shaders(), "furnace_0.5", 0.5f));
}

TEST_P(SurfaceCacheFurnaceGpu, Rho080ConvergesToTheAnalyticRadiance) {
    LUMINA_REQUIRE_KERNELS();
    expectConverged(runFurnace(device(), shaders(), "furnace_0.8", 0.8f));
}

TEST_P(SurfaceCacheFurnaceGpu, Rho095ConvergesToTheAnalyticRadiance) {
    LUMINA_REQUIRE_KERNELS();
    expectConverged(runFurnace(device(), shaders(), "furnace_0.95", 0.95f));
}

// rho = 0.99 needs 619 bounces (the cap, 768, allows them), an albedo dithered between its two
// neighbouring halves (0.989746 alone gives 97.5) and unbiased half rounding in the loop (nearest
// rounding stalled near 94.5): docs/gi.md, energy. Measured on lavapipe: -0.28 %, worst texel
// 0.75 % (-2.87 % / 4.06 % while the lookups that turn the normal to face the ray read zero at
// a solid's convex edges; -0.19 % / 0.25 % before they turned it). Bounds: 1 % / 1.5 %.
TEST_P(SurfaceCacheFurnaceGpu, Rho099ConvergesToTheAnalyticRadiance) {
    LUMINA_REQUIRE_KERNELS();
    const FurnaceResult r = runFurnace(device(), shaders(), "furnace_0.99", 0.99f);
    expectRaysFindSurfaces(r);
    EXPECT_TRUE(r.finite);
    EXPECT_GT(r.texels, 6u * 60u * 60u);
    EXPECT_NEAR(r.meanRelError, 0.0f, 0.01f);
    EXPECT_LT(r.maxAbsRelError, 0.015f);
}

LUMINA_INSTANTIATE_GPU_TEST(SurfaceCacheFurnaceGpu);

} // namespace
} // namespace lumina::test
