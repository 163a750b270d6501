// The near-field trace (pass 5) on the GPU: mesh-SDF hits read their card's final lighting from
// the surface cache, misses go on to the far field from the near-field distance, and without a
// surface cache (or with a near-field distance of 0) the pass is skipped and nothing changes.
#include "gi/core/camera.h"
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/card_bvh.h"
#include "shaders/common/sdf_scene_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"
#include "tests/pathtracer/path_tracer_fixture.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/screen_probes/screen_probe_harness.h"
#include "tests/surface_cache/surface_cache_harness.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

using ProbeNearFieldGpuTest = GpuTest;
using ProbeNearFieldPathTracerGpuTest = PathTracerTest;

// The kernel's card lookup (probe_trace_near_field.hlsl, cardRadiance) on the read-back final
// layer: coverage-weighted bilinear around the point's texel, clamped into the card's rectangle.
glm::vec4 cardRadianceOnCpu(const gpu::SurfaceCard& card, const std::vector<glm::vec4>& finalLayer,
                            uint32_t atlasSize, glm::vec3 p) {
    const glm::vec2 rectMin(float(card.atlasRect.x), float(card.atlasRect.y));
    const glm::vec2 rectMax = rectMin + glm::vec2(float(card.atlasRect.z), float(card.atlasRect.w)) - 1.0f;
    const glm::vec2 texel = gpu::cardToAtlasTexel(card, glm::vec2(gpu::worldToCardSpace(card, p)));
    const glm::vec2 x = glm::clamp(texel - 0.5f, rectMin, rectMax);
    const glm::vec2 base = glm::floor(x), f = x - base;
    glm::vec4 sum(0.0f);
    for (uint32_t corner = 0; corner < 4; ++corner) {
        const glm::vec2 offset(float(corner & 1u), float(corner >> 1));
        const glm::vec2 w2 = glm::mix(1.0f - f, f, offset);
        const glm::uvec2 at(glm::min(base + offset, rectMax));
        const glm::vec4 v = finalLayer[size_t(at.y) * atlasSize + at.x];
        const float w = w2.x * w2.y * v.a;
        sum += glm::vec4(w * glm::vec3(v), w);
    }
    return sum.a > LUMINA_SP_MIN_COVERAGE ? glm::vec4(glm::vec3(sum) / sum.a, sum.a) : glm::vec4(0.0f);
}

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// The base colour of the material a card's instance is drawn with (the Cornell box's meshes have one).
glm::vec3 cardColour(const scene::Scene& scene, const surface_cache::SurfaceCards& cards, uint32_t card) {
    const scene::Mesh& mesh = scene.meshes[scene.instances[cards.instanceOf(card)].mesh];
    return glm::vec3(scene.materials[mesh.submeshes.front().material].baseColor);
}

// (a) and (c): in the emissive Cornell box with a converged surface cache, every ray the near field
// hits carries the final lighting of the card that owns its hit (the CPU owner rule and bilinear
// lookup on the read-back layer), rays towards the red and green walls carry their colours, the
// far field takes over only past the near-field distance, and every near-field output is finite.
TEST_P(ProbeNearFieldGpuTest, NearHitsReadTheirCardsFinalLightingAndEveryOutputIsFinite) {
    LUMINA_REQUIRE_KERNELS();
    constexpr float kNearField = 300.0f; // mm: most of the box's 555 from a wall
    gi::ScreenProbeSettings settings;
    settings.nearFieldDistance = kNearField;
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box"), kSize, kSize, settings);
    harness.useVoxelLighting(false); // far hits read the cache's voxel lighting
    harness.addSurfaceCache(cornellCacheSettings(), quickCacheLighting());
    ASSERT_LT(harness.renderUntilCacheConverged(40), 40u) << "the surface cache did not converge";
    const std::vector<std::string> passes = harness.render();
    const auto at = std::find(passes.begin(), passes.end(), gi::ProbeTraceNearFieldPass::kName);
    ASSERT_NE(at, passes.end());
    EXPECT_EQ(*(at + 1), gi::ProbeTraceFarFieldPass::kName);
    ASSERT_TRUE(harness.probes().nearFieldTraced());

    const gi::ScreenProbeResources& r = harness.probes().resources();
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
    const auto rays = harness.read<gpu::ProbeRay>(r.rays);
    const auto hits = harness.read<gpu::SdfHit>(r.hits);
    const auto near = harness.read<gpu::float4>(r.nearField);
    const auto radiance = harness.read<gpu::float4>(r.rayRadiance);
    const surface_cache::SurfaceCache& cache = harness.cache();
    const std::vector<glm::vec4> finalLayer = cache.readLayer(surface_cache::AtlasLayer::FinalLighting);
    const std::vector<gpu::SurfaceCard>& cards = cache.cards().cards();

    uint32_t rayCount = 0, cardHits = 0, voxelHits = 0, misses = 0, matched = 0, otherOwner = 0;
    uint32_t red = 0, redRight = 0, green = 0, greenRight = 0;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        for (uint32_t i = p * r.raysPerProbe; i < (p + 1) * r.raysPerProbe; ++i) {
            ++rayCount;
            const std::string where = "probe " + std::to_string(p) + " ray " + std::to_string(i);
            ASSERT_TRUE(finite(near[i])) << where;
            ASSERT_TRUE(finite(radiance[i])) << where;
            const uint32_t source = uint32_t(near[i].w);
            ASSERT_EQ(near[i].w, float(source)) << where;
            ASSERT_LE(source, LUMINA_SP_NEAR_VOXEL) << where;
            const float t = hits[i].positionAndT.w;
            if (source == LUMINA_SP_NEAR_MISS) {
                // The far field's record: a miss, or a hit from the near-field distance on.
                ++misses;
                EXPECT_TRUE(hits[i].ids.z != 0 || t >= kNearField * (1.0f - 1e-5f)) << where << ": t " << t;
                continue;
            }
            // A near hit keeps the near field's record, and shading passes its radiance on.
            EXPECT_EQ(hits[i].ids.z, 0u) << where;
            EXPECT_LE(t, kNearField) << where;
            EXPECT_EQ(glm::vec4(radiance[i]), glm::vec4(glm::vec3(near[i]), 1.0f)) << where;
            if (source == LUMINA_SP_NEAR_VOXEL) {
                ++voxelHits;
                continue;
            }
            ++cardHits;
            const glm::vec3 position(hits[i].positionAndT);
            glm::vec3 normal(hits[i].normalAndCoverage);
            if (glm::dot(normal, normal) == 0.0f) {
                normal = -glm::vec3(rays[i].directionAndWeight);
            }
            // As the kernel: the normal turned to face the ray (sdfFacingNormal), and the cards that
            // face away from the ray skipped (sdfSeenFrom, cardFacesRay).
            const glm::vec3 seenFrom = t > 0.0f ? glm::vec3(rays[i].directionAndWeight) : glm::vec3(0.0f);
            if (glm::dot(normal, seenFrom) > 0.0f) {
                normal = -normal;
            }
            const surface_cache::CardOwner owner =
                findCardOwner(cache.cardBvh(), cards, position, normal, hits[i].ids.x, seenFrom);
            if (owner.card == LUMINA_NO_CARD) {
                ++otherOwner;
                continue;
            }
            const glm::vec4 expected =
                cardRadianceOnCpu(cards[owner.card], finalLayer, cache.atlas().size(), position);
            const glm::vec3 got(near[i]);
            const bool same =
                expected.a > 0.0f && glm::all(glm::lessThanEqual(glm::abs(got - glm::vec3(expected)),
                                                                 1e-3f * glm::vec3(expected) + 1e-6f));
            // Rounding (fused multiply-adds) may swap two cards whose owner scores agree to 1e-6.
            if (!same) {
                ++otherOwner;
                continue;
            }
            ++matched;
            const glm::vec3 colour = cardColour(harness.scene(), cache.cards(), owner.card);
            if (colour.r > 4.0f * colour.g) {
                ++red;
                redRight += got.r > 2.0f * got.g;
            } else if (colour.g > 2.0f * colour.r) {
                ++green;
                // At least as green as red: a texel at the open front edge, lit mostly by the red
                // wall facing it, reads r = g in half floats (16-texel tiles, commit after e2d46e6).
                greenRight += got.g >= got.r;
            }
        }
    }
    std::cout << rayCount << " rays: " << cardHits << " read a card (" << matched << " as the CPU does), "
              << voxelHits << " the voxel lighting, " << misses << " near misses; towards the red wall "
              << red << ", the green wall " << green << '\n';
    EXPECT_GT(cardHits, rayCount / 3);
    EXPECT_LT(voxelHits, cardHits / 20);
    EXPECT_GT(misses, 0u);
    EXPECT_GE(matched, cardHits * 99 / 100);
    EXPECT_LE(otherOwner, cardHits / 100);
    EXPECT_GT(red, 20u);
    EXPECT_GT(green, 20u);
    EXPECT_EQ(redRight, red);
    EXPECT_EQ(greenRight, green);
}

// (b): with no surface cache, and with one but a near-field distance of 0, the pass is skipped
// with its reason, and every buffer the far field and shading write, and the result, are bit for
// bit the same in both. A bad surface cache view is refused by name before anything is recorded.
TEST_P(ProbeNearFieldGpuTest, WithoutCacheOrDistanceTheNearFieldIsSkippedAndNothingChanges) {
    LUMINA_REQUIRE_KERNELS();
    constexpr uint32_t kSmall = 32;
    const auto fill = [](uint32_t x, uint32_t y, uint32_t z) {
        return glm::vec4(0.1f * float(x), 0.05f * float(y), 0.02f * float(z + 1), 1.0f);
    };
    ScreenProbeHarness without(device(), shaders(), scene::loadScene("cornell_box_point"), kSmall, kSmall);
    ScreenProbeHarness zero(device(), shaders(), scene::loadScene("cornell_box_point"), kSmall, kSmall,
                            {.nearFieldDistance = 0.0f});
    zero.addSurfaceCache(cornellCacheSettings(), quickCacheLighting());
    for (ScreenProbeHarness* h : {&without, &zero}) {
        h->setSky(glm::vec3(0.2f, 0.3f, 0.4f));
        h->fillVoxels(fill);
    }
    for (int frame = 0; frame < 3; ++frame) {
        for (ScreenProbeHarness* h : {&without, &zero}) {
            const std::vector<std::string> passes = h->render();
            EXPECT_EQ(std::count(passes.begin(), passes.end(), gi::ProbeTraceNearFieldPass::kName), 0);
            EXPECT_FALSE(h->probes().nearFieldTraced());
        }
        EXPECT_EQ(skipReason(without.skipped(), gi::ProbeTraceNearFieldPass::kName),
                  "no surface cache given");
        EXPECT_EQ(skipReason(zero.skipped(), gi::ProbeTraceNearFieldPass::kName), "nearFieldDistance is 0");
    }
    const auto bytes = [&](ScreenProbeHarness& h, const rhi::BufferHandle& buffer) {
        return h.read<uint32_t>(buffer);
    };
    const gi::ScreenProbeResources& a = without.probes().resources();
    const gi::ScreenProbeResources& b = zero.probes().resources();
    const uint32_t cur = without.probes().current();
    EXPECT_TRUE(bytes(without, a.hits) == bytes(zero, b.hits)) << "hits";
    EXPECT_TRUE(bytes(without, a.rayRadiance) == bytes(zero, b.rayRadiance)) << "ray radiance";
    EXPECT_TRUE(bytes(without, a.history[cur]) == bytes(zero, b.history[cur])) << "history";
    const image::Image ea = without.read(without.probes().irradiance());
    const image::Image eb = zero.read(zero.probes().irradiance());
    uint32_t differ = 0, lit = 0;
    for (uint32_t y = 0; y < kSmall; ++y) {
        for (uint32_t x = 0; x < kSmall; ++x) {
            differ += ea.rgbAt(x, y).r != eb.rgbAt(x, y).r || ea.rgbAt(x, y).g != eb.rgbAt(x, y).g ||
                      ea.rgbAt(x, y).b != eb.rgbAt(x, y).b || ea.at("A", x, y) != eb.at("A", x, y);
            lit += ea.rgbAt(x, y).g > 0.0f;
        }
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(lit, kSmall * kSmall / 4);

    // Refused by name, before anything is recorded.
    gi::PipelineCache pipelines(device(), shaders());
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    gi::FrameContext frame(pipelines, *list, 0);
    const scene::Camera camera = zero.scene().camera;
    gi::SurfaceCacheView view = gi::surfaceCacheView(zero.cache());
    const auto refused = [&](const gi::SurfaceCacheView& bad, const std::string& what) {
        try {
            zero.probes().record(frame, {.gbuffer = zero.renderer().gbuffer(),
                                         .camera = camera,
                                         .sdf = zero.sdf(),
                                         .sky = zero.sceneSky(),
                                         .voxelLighting = {},
                                         .surfaceCache = bad});
            ADD_FAILURE() << what << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    gi::SurfaceCacheView noBvh = view;
    noBvh.cardBvh = nullptr;
    refused(noBvh, "card BVH buffer missing");
    gi::SurfaceCacheView wrongLayer = view;
    wrongLayer.finalLighting = view.voxelLighting;
    refused(wrongLayer, "final lighting");
    gi::SurfaceCacheView noGrid = view;
    noGrid.voxelGrid.dims = glm::uvec3(0);
    refused(noGrid, "voxel grid");
    list->end();
}

// A near field that reaches the rays' end (the presets' since docs/gi.md 33.) skips the far field
// with its reason, and its misses read the sky: every ray's radiance is bit for bit what it is
// when the far field runs on past a scene it cannot hit any more (the box's diagonal is 965 mm).
TEST_P(ProbeNearFieldGpuTest, ANearFieldToTheRaysEndSkipsTheFarFieldAndChangesNothing) {
    LUMINA_REQUIRE_KERNELS();
    constexpr uint32_t kSmall = 32;
    constexpr float kAcross = 1200.0f; // mm
    ScreenProbeHarness whole(device(), shaders(), scene::loadScene("cornell_box_point"), kSmall, kSmall,
                             {.maxTraceDistance = kAcross, .nearFieldDistance = kAcross});
    ScreenProbeHarness beyond(device(), shaders(), scene::loadScene("cornell_box_point"), kSmall, kSmall,
                              {.maxTraceDistance = 2.0f * kAcross, .nearFieldDistance = kAcross});
    for (ScreenProbeHarness* h : {&whole, &beyond}) {
        h->setSky(glm::vec3(0.2f, 0.3f, 0.4f));
        h->useVoxelLighting(false);
        h->addSurfaceCache(cornellCacheSettings(), quickCacheLighting());
    }
    for (int frame = 0; frame < 3; ++frame) {
        const std::vector<std::string> skipped = whole.render();
        const std::vector<std::string> traced = beyond.render();
        EXPECT_EQ(std::count(skipped.begin(), skipped.end(), gi::ProbeTraceFarFieldPass::kName), 0);
        EXPECT_EQ(std::count(traced.begin(), traced.end(), gi::ProbeTraceFarFieldPass::kName), 1);
        EXPECT_EQ(skipReason(whole.skipped(), gi::ProbeTraceFarFieldPass::kName),
                  "the near field reaches the trace's end");
    }
    const std::vector<glm::vec4> a = whole.read<glm::vec4>(whole.probes().resources().rayRadiance);
    const std::vector<glm::vec4> b = beyond.read<glm::vec4>(beyond.probes().resources().rayRadiance);
    ASSERT_EQ(a.size(), b.size());
    uint32_t differ = 0, sky = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        differ += a[i] != b[i];
        sky += a[i].a == 0.0f && a[i].b > 0.0f; // a miss (alpha 0) that read the sky
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(sky, 0u) << "no ray left the open box: the misses were not exercised";
}

// The summed weight of the covered voxels around p in a coverage-weighted trilinear lookup of the
// read-back voxel lighting (voxelLightingTrilinear in voxel_lighting_sampling.hlsli): 0 where the
// lookup finds no surface.
float voxelCoverage(const std::vector<glm::vec4>& voxels, const gpu::VoxelGridInfo& grid, glm::vec3 p) {
    const glm::vec3 local = (p - grid.boxMin) / grid.voxelSize - 0.5f;
    const glm::ivec3 base(glm::floor(local));
    const glm::vec3 f = local - glm::vec3(base);
    float weight = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 v = base + offset;
        if (glm::any(glm::lessThan(v, glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(v, glm::ivec3(grid.dims)))) {
            continue;
        }
        const glm::vec3 w3 = glm::mix(1.0f - f, f, glm::vec3(offset));
        weight += w3.x * w3.y * w3.z * voxels[(size_t(v.z) * grid.dims.y + v.y) * grid.dims.x + v.x].a;
    }
    return weight;
}

// Not a test: how often a far-field hit finds no surface in the surface cache's voxel lighting (and
// reads black): looked up at the hit as a caller's volume is, leaning back 0.5 and 1.5 voxels as
// sampleVoxelLighting does (both on the CPU), and walking back as the shading does
// (coneHitVoxelRadiance, on the GPU); the emissive Cornell box with the near field off. For
// docs/screen_probes.md: --gtest_also_run_disabled_tests --gtest_filter='*PrintFarHitVoxelCoverage*'.
TEST_P(ProbeNearFieldGpuTest, DISABLED_PrintFarHitVoxelCoverage) {
    LUMINA_REQUIRE_KERNELS();
    ScreenProbeHarness harness(device(), shaders(), scene::loadScene("cornell_box"), kSize, kSize,
                               {.nearFieldDistance = 0.0f});
    harness.useVoxelLighting(false);
    harness.addSurfaceCache(cornellCacheSettings(), quickCacheLighting());
    harness.renderUntilCacheConverged(40);
    const gi::ScreenProbeResources& r = harness.probes().resources();
    const auto hits = harness.read<gpu::SdfHit>(r.hits);
    const auto radiance = harness.read<gpu::float4>(r.rayRadiance);
    const auto probes = harness.read<gpu::ScreenProbe>(r.probes[harness.probes().current()]);
    const std::vector<glm::vec4> voxels = harness.cache().readVoxelLighting();
    const gpu::VoxelGridInfo& grid = harness.cache().voxelLighting().grid();
    const float voxel = grid.voxelSize;
    uint32_t farHits = 0, atHit = 0, leaned = 0, walked = 0;
    for (size_t i = 0; i < hits.size(); ++i) {
        if (probes[i / r.raysPerProbe].info.x != LUMINA_SP_PROBE_VALID || hits[i].ids.z != 0) {
            continue;
        }
        ++farHits;
        const glm::vec3 p(hits[i].positionAndT), n(hits[i].normalAndCoverage);
        atHit += voxelCoverage(voxels, grid, p) == 0.0f;
        leaned += voxelCoverage(voxels, grid, p - 0.5f * voxel * n) == 0.0f &&
                  voxelCoverage(voxels, grid, p - 1.5f * voxel * n) == 0.0f;
        walked += radiance[i].x == 0.0f && radiance[i].y == 0.0f && radiance[i].z == 0.0f;
    }
    std::cout << farHits << " far-field hits find no surface: at the hit " << atHit
              << ", leaning 0.5 and 1.5 voxels " << leaned << ", walking back " << walked << '\n';
}

// relMSE = mean((x - r)^2 / (r^2 + 0.01)) over RGB, and the ratio of the means.
struct Error {
    double sum = 0.0, mean = 0.0, meanReference = 0.0;
    uint32_t pixels = 0;
    void add(const glm::vec3& x, const image::Rgb& r) {
        const double ref[3] = {r.r, r.g, r.b};
        for (int c = 0; c < 3; ++c) {
            sum += (x[c] - ref[c]) * (x[c] - ref[c]) / (ref[c] * ref[c] + 0.01);
            mean += x[c];
            meanReference += ref[c];
        }
        ++pixels;
    }
    void print(const std::string& name) const {
        std::cout << name << ": relMSE " << sum / (3.0 * pixels) << ", mean / path tracer "
                  << mean / meanReference << " (" << pixels << " pixels)\n";
    }
};

// Not a test: the gather against the path tracer in the emissive Cornell box, where every surface
// but the light is lit indirectly, L = albedo / pi x E (the light's own pixels left out), after 40
// frames, for near-field distances 0 (far field only), the default and 300 mm, and with the cache's
// voxel lighting handed over as a plain volume (far hits looked up at the hit); beside it the
// surface cache's own final layer at the same pixels, which the near field reads. The cache at the
// quality of SurfaceCacheCornellGpu (mesh and global SDFs of 64, 4 mm texels, 20 bounces and 16
// refinement passes). About five minutes on lavapipe. For docs/screen_probes.md:
// --gtest_also_run_disabled_tests --gtest_filter='*PrintAgainstThePathTracer*'.
TEST_P(ProbeNearFieldPathTracerGpuTest, DISABLED_PrintAgainstThePathTracer) {
    const scene::Scene scene = scene::loadScene("cornell_box");
    const gi::PathTracerResult reference =
        render(scene, {.width = kSize, .height = kSize, .jitter = false}, 256);
    std::cout << "path tracer: 256 spp, mean relative standard error " << reference.meanRelativeStandardError
              << '\n';
    surface_cache::SurfaceCacheSettings cache;
    cache.atlasSize = 1024;
    cache.texelsPerUnit = 0.25f;
    cache.minPaddingUnits = 10.0f;
    sdf::SceneSdfSettings sdfs = ScreenProbeHarness::sdfSettings();
    sdfs.mesh.resolution = 64;
    sdfs.globalResolution = 64;
    struct Config {
        const char* name;
        std::optional<float> nearField;
        bool plainVolume = false;
    };
    bool first = true;
    for (const Config& config : {Config{"near field default", std::nullopt}, Config{"near field 300", 300.0f},
                                 Config{"far field only", 0.0f},
                                 Config{"far field only, cache volume as a plain volume", 0.0f, true}}) {
        ScreenProbeHarness harness(device(), shaders(), scene, kSize, kSize,
                                   {.nearFieldDistance = config.nearField}, 8, sdfs);
        harness.addSurfaceCache(cache);
        harness.useVoxelLighting(false);
        harness.useCacheVolumeAsPlainVolume(config.plainVolume);
        const uint32_t converged = harness.renderUntilCacheConverged(100);
        for (uint32_t frame = converged; frame < 40; ++frame) {
            harness.render();
        }
        const image::Image albedo = harness.read(harness.renderer().gbuffer().albedo);
        const image::Image material = harness.read(harness.renderer().gbuffer().material);
        const image::Image position = harness.read(harness.renderer().gbuffer().position);
        const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
        const image::Image irradiance = harness.read(harness.probes().irradiance());
        const surface_cache::SurfaceCache& c = harness.cache();
        const std::vector<glm::vec4> finalLayer = c.readLayer(surface_cache::AtlasLayer::FinalLighting);
        Error gather, cached;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                const image::Rgb le = material.rgbAt(x, y);
                if (albedo.at("A", x, y) == 0.0f || le.r + le.g + le.b > 0.0f) {
                    continue;
                }
                const image::Rgb a = albedo.rgbAt(x, y), e = irradiance.rgbAt(x, y),
                                 ref = reference.image.rgbAt(x, y);
                gather.add(glm::vec3(a.r * e.r, a.g * e.g, a.b * e.b) / kPi, ref);
                const image::Rgb p = position.rgbAt(x, y), n = normal.rgbAt(x, y);
                const glm::vec3 world(p.r, p.g, p.b), facing = glm::normalize(glm::vec3(n.r, n.g, n.b));
                const surface_cache::CardOwner owner =
                    findCardOwner(c.cardBvh(), c.cards().cards(), world, facing);
                if (first && owner.card != LUMINA_NO_CARD) {
                    cached.add(glm::vec3(cardRadianceOnCpu(c.cards().cards()[owner.card], finalLayer,
                                                           c.atlas().size(), world)),
                               ref);
                }
            }
        }
        if (first) {
            cached.print("surface cache final layer");
            first = false;
        }
        const gpu::SdfSceneInfo grid = harness.sdf().sceneInfo();
        const float diagonal = glm::length(grid.globalMax - grid.globalMin);
        gather.print(std::string(config.name) + " (" +
                     std::to_string(config.nearField.value_or(
                         gi::ScreenProbeSettings::kNearFieldGridFraction * diagonal)) +
                     ")");
    }
}

LUMINA_INSTANTIATE_GPU_TEST(ProbeNearFieldGpuTest);
LUMINA_INSTANTIATE_GPU_TEST(ProbeNearFieldPathTracerGpuTest);

} // namespace
} // namespace lumina::test
