// Voxel lighting's inject (gi/surface_cache/voxel_lighting_pass.h): a voxel face holds the mean
// radiance over the surface area in it, not over its texels. Two coplanar emissive strips of
// different radiance share a column of voxels; their cards have different texel densities (a card
// is rounded up to whole tiles), so a mean over texels would lean towards the narrow strip.
#include "gi/scene/mesh_builder.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class VoxelLightingGpu : public GpuTest {};

// A 2 x 2 floor facing +y, cut at x = kSeam into a wide strip and a narrow one, each its own
// instance (so its own card), emitting kWideRadiance and kNarrowRadiance.
constexpr float kSeam = 0.8f;
constexpr float kWideRadiance = 1.0f;
constexpr float kNarrowRadiance = 4.0f;
// 32 texels per metre: the wide strip's 1.8 m take 57.6 texels, rounded to 64 (1.11 times the
// nominal density); the narrow strip's 0.2 m take 6.4, rounded to 16 (2.5 times).
constexpr float kTexelsPerUnit = 32.0f;
// Odd, so that the floor (at the grid's centre height) lies mid-voxel; voxels of 2/7 m: the
// column at x in [5/7, 1] holds 0.086 m of the wide strip and all of the narrow one.
constexpr uint32_t kVoxelResolution = 9;

scene::Scene twoStripFloor() {
    scene::Scene s;
    s.name = "two emissive strips";
    s.materials.push_back({.name = "wide",
                           .baseColor = glm::vec4(glm::vec3(0.5f), 1.0f),
                           .emission = glm::vec3(kWideRadiance)});
    s.materials.push_back({.name = "narrow",
                           .baseColor = glm::vec4(glm::vec3(0.5f), 1.0f),
                           .emission = glm::vec3(kNarrowRadiance)});
    const auto strip = [&](const char* name, uint32_t material, float x0, float x1) {
        scene::MeshBuilder b(name);
        b.material(material);
        b.quad({x0, 0.0f, 1.0f}, {x1, 0.0f, 1.0f}, {x1, 0.0f, -1.0f}, {x0, 0.0f, -1.0f});
        s.meshes.push_back(b.finish());
        s.instances.push_back(
            {.mesh = uint32_t(s.meshes.size() - 1), .transform = glm::mat4(1.0f), .name = name});
    };
    strip("wide", 0, -1.0f, kSeam);
    strip("narrow", 1, kSeam, 1.0f);
    s.image = {64, 64};
    scene::finishCamera(s);
    return s;
}

// World area of one texel of `card`: card space maps the card's extent to [0, 1]^2 over its
// rectangle, so the rows of worldToCard have the inverse width and height as lengths.
double texelArea(const gpu::SurfaceCard& card) {
    return 1.0 / (double(glm::length(glm::vec3(card.worldToCard0))) *
                  double(glm::length(glm::vec3(card.worldToCard1))) * double(card.atlasRect.z) *
                  double(card.atlasRect.w));
}

struct VoxelSums {
    double area = 0.0, areaRadiance = 0.0;
    double texels = 0.0, texelRadiance = 0.0;
};

TEST_P(VoxelLightingGpu, AVoxelHoldsTheMeanOverAreaNotOverTexels) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheSettings settings;
    settings.atlasSize = 128;
    settings.texelsPerUnit = kTexelsPerUnit;
    SurfaceLightingSettings lighting;
    lighting.voxelResolution = kVoxelResolution;
    SurfaceCacheHarness h(device(), shaders(), twoStripFloor(), settings, lighting);
    // One update: capture, combine, inject (reads the final layer combine just wrote), radiosity
    // (writes the indirect layer, which the final layer takes in only at the next combine).
    h.update();

    const std::vector<gpu::SurfaceCard>& cards = h.cache.cards().cards();
    ASSERT_EQ(cards.size(), 2u);
    const double wideArea = texelArea(cards[h.cache.cards().firstCard(0)]);
    const double narrowArea = texelArea(cards[h.cache.cards().firstCard(1)]);
    ASSERT_GT(wideArea / narrowArea, 2.0) << "the strips' cards must differ in density for this test";

    // The CPU's sums per voxel, over the texels inject takes: captured, and facing +y (a texel's
    // weight on a face is its normal's squared component there; these are all 1 on +y).
    const uint32_t size = h.cache.atlas().size();
    const std::vector<glm::vec4> final = h.cache.readLayer(AtlasLayer::FinalLighting);
    const std::vector<glm::vec4> normal = h.cache.readLayer(AtlasLayer::Normal);
    const std::vector<glm::vec3> world = atlasWorldPositions(device(), h.cache);
    const gpu::VoxelGridInfo& grid = h.cache.voxelLighting().grid();
    std::map<std::tuple<uint32_t, uint32_t, uint32_t>, VoxelSums> sums;
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const size_t i = size_t(y) * size + x;
            const uint32_t card = atlasTexelOwner(h.cache, x, y);
            if (card == kNoOwner || normal[i].a == 0.0f) {
                continue;
            }
            const glm::ivec3 voxel(glm::floor((world[i] - grid.boxMin) / grid.voxelSize));
            VoxelSums& s = sums[{uint32_t(voxel.x), uint32_t(voxel.y), uint32_t(voxel.z)}];
            const double area = texelArea(cards[card]);
            s.area += area;
            s.areaRadiance += area * final[i].r;
            s.texels += 1.0;
            s.texelRadiance += final[i].r;
        }
    }

    // +y is face 2; the volume's rows hold LUMINA_VOXEL_FACES x dims.x texels (face f of voxel x
    // at f * dims.x + x), then y, then z.
    const std::vector<glm::vec4> volume = h.cache.readVoxelLighting();
    constexpr uint32_t kPlusY = 2;
    uint32_t compared = 0, mixed = 0;
    double worst = 0.0;
    for (const auto& [key, s] : sums) {
        const auto [vx, vy, vz] = key;
        ASSERT_LT(vx, grid.dims.x);
        ASSERT_LT(vz, grid.dims.z);
        const glm::vec4 v = volume[(size_t(vz) * grid.dims.y + vy) * grid.dims.x * LUMINA_VOXEL_FACES +
                                   kPlusY * grid.dims.x + vx];
        const double areaMean = s.areaRadiance / s.area;
        const double texelMean = s.texelRadiance / s.texels;
        EXPECT_EQ(v.a, 1.0f) << "voxel (" << vx << ", " << vy << ", " << vz << ") received texels";
        // Within the fixed point's rounding of each card's weight (the narrow strip's 0.4 rounds to
        // 102/256, 0.4 % low) and RGBA16F's; the two means differ by 14 % where the strips mix.
        const double error = std::abs(v.r - areaMean) / areaMean;
        worst = std::max(worst, error);
        EXPECT_LT(error, 0.01) << "voxel (" << vx << ", " << vy << ", " << vz << "): " << v.r
                               << ", the mean over area is " << areaMean << ", over texels " << texelMean;
        ++compared;
        if (std::abs(texelMean - areaMean) / areaMean > 0.05) {
            ++mixed;
        }
    }
    // The seam's column of voxels (7 along z) holds both strips: there the two means differ by 14 %.
    EXPECT_GE(mixed, 7u) << "voxels where the mean over texels is 5 % off the mean over area";
    EXPECT_GT(compared, 30u);
    std::printf("voxel inject: %u voxels, %u of them mixing both strips, worst relative error %.5f\n",
                compared, mixed, worst);
}

TEST_P(VoxelLightingGpu, RefusesANominalTexelAreaThatIsNotPositive) {
    LUMINA_REQUIRE_KERNELS();
    SurfaceCacheHarness h(device(), shaders(), twoStripFloor(), SurfaceCacheSettings{});
    const gpu::VoxelGridInfo& grid = h.cache.voxelLighting().grid();
    for (const float area : {0.0f, -1.0f, NAN, INFINITY}) {
        EXPECT_THROW(VoxelLightingPass(device(), grid, h.sdf, area), std::invalid_argument) << area;
    }
}

} // namespace

LUMINA_INSTANTIATE_GPU_TEST(VoxelLightingGpu);

} // namespace lumina::test
