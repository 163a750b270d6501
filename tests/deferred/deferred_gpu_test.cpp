// The deferred renderer on the GPU (lavapipe in CI), validation and synchronization
// validation on: GBuffer contents, direct light against the shared light model, the sun's shadow
// at the foot of a wall, shadow-pass skipping, the shadow budget, emission, culling of mirrored
// and double-sided instances, the cube-map convention of the point shadows, the composite and
// the buffer dump.
#include "gi/image/display.h"
#include "gi/image/exr.h"
#include "gi/scene/mesh_builder.h"
#include "gi/scene/scene_loader.h"
#include "shaders/common/constants_shared.h"
#include "tests/deferred/deferred_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <random>

namespace lumina::test {
namespace {

using DeferredGpuTest = GpuTest;

constexpr uint32_t kSize = 64;

TEST_P(DeferredGpuTest, GBufferHoldsTheCornellBox) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), kSize, kSize);
    harness.render();
    const auto [albedo, normal, material, position, depth] = harness.readGBuffer();
    // Red wall on the left (x = 556 mm, facing -x), green on the right, ceiling, back wall.
    struct Probe {
        uint32_t x, y;
        gpu::float3 albedo, normal;
        int axis;      // the coordinate the surface lies at
        float planeMm; // ... and its value, within a millimetre or so
        uint32_t materialIndex;
    };
    const Probe probes[] = {
        {3, 32, {0.63f, 0.065f, 0.05f}, {-1, 0, 0}, 0, 554.0f, 1},
        {60, 32, {0.14f, 0.45f, 0.091f}, {1, 0, 0}, 0, 0.0f, 2},
        {32, 2, {0.725f, 0.71f, 0.68f}, {0, -1, 0}, 1, 548.8f, 0},
        {32, 16, {0.725f, 0.71f, 0.68f}, {0, 0, -1}, 2, 559.2f, 0},
    };
    for (const Probe& probe : probes) {
        const std::string where = "pixel " + std::to_string(probe.x) + "," + std::to_string(probe.y);
        const gpu::float3 a = rgbAt(albedo, probe.x, probe.y);
        const gpu::float3 n = rgbAt(normal, probe.x, probe.y);
        const gpu::float3 p = rgbAt(position, probe.x, probe.y);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a[c], probe.albedo[c], 0.5f / 255.0f + 1e-6f) << where << " albedo " << c;
            // The published walls lean by up to 0.4 degrees: normals are near the axes.
            EXPECT_NEAR(n[c], probe.normal[c], 0.02f) << where << " normal " << c;
        }
        EXPECT_NEAR(p[probe.axis], probe.planeMm, 3.0f) << where << " position";
        EXPECT_EQ(normal.at("A", probe.x, probe.y), 1.0f) << where;
        EXPECT_EQ(albedo.at("A", probe.x, probe.y), 1.0f) << where;
        EXPECT_EQ(material.at("A", probe.x, probe.y), float(probe.materialIndex)) << where;
        EXPECT_EQ(rgbAt(material, probe.x, probe.y), gpu::float3(0.0f)) << where << " emission";
        // w: distance along the camera's forward axis (+z from z = -800 mm).
        EXPECT_NEAR(position.at("A", probe.x, probe.y), p.z + 800.0f, 0.01f) << where;
        const float d = depth.at("R", probe.x, probe.y);
        EXPECT_GT(d, 0.0f) << where;
        EXPECT_LT(d, 1.0f) << where;
    }
}

TEST_P(DeferredGpuTest, DirectLightIsTheSharedLightModelWhereLitAndDarkInShadow) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), kSize, kSize);
    harness.render();
    const GBufferImages gbuffer = harness.readGBuffer();
    const image::Image direct = harness.read(harness.renderer().direct());
    uint32_t covered = 0, lit = 0, dark = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (gbuffer.normal.at("A", x, y) == 0.0f) {
                EXPECT_EQ(rgbAt(direct, x, y), gpu::float3(0.0f)) << "sky is black: " << x << "," << y;
                continue;
            }
            ++covered;
            const Unshadowed expected = unshadowed(harness.renderer().lights(), gbuffer, x, y);
            const gpu::float3 got = rgbAt(direct, x, y) - expected.emission;
            if (expected.reflected.x <= 0.0f) { // turned away from the light
                EXPECT_EQ(got, gpu::float3(0.0f)) << x << "," << y;
                continue;
            }
            // Visibility = what arrived over what would arrive unshadowed; one value for all
            // three channels, within the precision of the RGBA16F target.
            const float visibility = got.x / expected.reflected.x;
            ASSERT_TRUE(std::isfinite(visibility)) << x << "," << y;
            EXPECT_GE(visibility, -2e-3f) << x << "," << y;
            EXPECT_LE(visibility, 1.0f + 2e-3f) << x << "," << y;
            for (int c = 1; c < 3; ++c) {
                EXPECT_NEAR(got[c], visibility * expected.reflected[c], 2e-3f * expected.reflected[c] + 1e-6f)
                    << x << "," << y << " channel " << c;
            }
            lit += visibility > 0.998f ? 1 : 0;
            dark += visibility < 0.002f ? 1 : 0;
        }
    }
    EXPECT_GT(covered, kSize * kSize * 9 / 10);
    // Most of the box sees the light; the blocks' shadows and their own far sides do not.
    EXPECT_GT(lit, covered / 2) << "lit " << lit << " of " << covered;
    EXPECT_GT(dark, covered / 20) << "dark " << dark << " of " << covered;
}

TEST_P(DeferredGpuTest, PointShadowsRenderOnlyWhenTheirLightOrTheGeometryChanges) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 32, 32);
    auto frame = harness.render();
    EXPECT_TRUE(frame.ran("point shadows"));
    EXPECT_EQ(frame.skipReason("sun shadow"), "no directional light");
    for (const char* pass : {"gbuffer visibility", "gbuffer resolve", "direct light", "composite"}) {
        EXPECT_TRUE(frame.ran(pass)) << pass;
    }
    for (int i = 0; i < 2; ++i) {
        frame = harness.render();
        EXPECT_FALSE(frame.ran("point shadows"));
        EXPECT_EQ(frame.skipReason("point shadows"), "unchanged since frame 0");
        EXPECT_TRUE(frame.ran("direct light"));
    }
    std::vector<scene::Light> lights = harness.scene().lights;
    lights[0].position.y -= 100.0f;
    harness.renderer().setLights(lights);
    EXPECT_TRUE(harness.render().ran("point shadows"));
    EXPECT_EQ(harness.render().skipReason("point shadows"), "unchanged since frame 3");
    harness.renderer().geometryChanged(harness.scene().worldBounds());
    EXPECT_TRUE(harness.render().ran("point shadows"));
    // Moving the camera re-renders neither shadow map.
    scene::Camera camera = harness.scene().camera;
    camera.position.x += 50.0f;
    harness.renderer().setCamera(camera);
    EXPECT_EQ(harness.render().skipReason("point shadows"), "unchanged since frame 5");
}

TEST_P(DeferredGpuTest, SunShadowRendersOnlyWhenTheSunMoves) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("open_top_box"), 32, 32);
    auto frame = harness.render();
    EXPECT_TRUE(frame.ran("sun shadow"));
    EXPECT_EQ(frame.skipReason("point shadows"), "no point or spot lights");
    frame = harness.render();
    EXPECT_FALSE(frame.ran("sun shadow"));
    EXPECT_EQ(frame.skipReason("sun shadow"), "unchanged since frame 0");
    std::vector<scene::Light> lights = harness.scene().lights;
    lights[0].direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
    harness.renderer().setLights(lights);
    EXPECT_TRUE(harness.render().ran("sun shadow"));
    EXPECT_EQ(harness.render().skipReason("sun shadow"), "unchanged since frame 2");
}

// A zero-thickness wall standing on the edge of a floor, the sun behind it: the floor is in the
// wall's shadow right up to the wall's foot. Two things used to light a strip of it a shadow
// texel or two wide (docs/deferred.md, "Shadows"): the PCF counted as lit the texels beyond the
// wall, where nothing was drawn, and the normal offset lifted the receiver above the wall's foot.
// A coarse map (64 texels, 3.5 cm) makes that strip several pixels wide.
TEST_P(DeferredGpuTest, TheSunDoesNotReachAFloorThroughTheFootOfAWall) {
    scene::Scene scene;
    scene.name = "wall_on_floor";
    scene.materials = {{.name = "grey", .baseColor = {0.5f, 0.5f, 0.5f, 1.0f}, .doubleSided = true}};
    scene::MeshBuilder floor("floor");
    floor.quad({-1, 0, 0}, {-1, 0, 2}, {1, 0, 2}, {1, 0, 0}); // front +y; nothing lies beyond z = 0
    scene::MeshBuilder wall("wall");
    wall.quad({-1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 1, 0});
    scene.meshes = {floor.finish(), wall.finish()};
    scene.instances = {{.mesh = 0, .transform = glm::mat4(1.0f), .name = "floor"},
                       {.mesh = 1, .transform = glm::mat4(1.0f), .name = "wall"}};
    // Travelling +z and down two to one: the 1 m wall shades the floor up to z = 0.5.
    scene.lights.push_back({.type = scene::LightType::Directional,
                            .name = "sun",
                            .direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.5f))});
    scene.camera = {.name = "camera",
                    .position = {0, 3, 0.5f},
                    .forward = {0, -1, 0},
                    .up = {0, 0, -1},
                    .fovY = 0.4f,
                    .nearPlane = 0.1f,
                    .farPlane = 100.0f};
    scene.image = {kSize, kSize};

    DeferredHarness harness(device(), shaders(), scene, kSize, kSize, nullptr, 64);
    harness.render();
    const GBufferImages gbuffer = harness.readGBuffer();
    const image::Image direct = harness.read(harness.renderer().direct());
    uint32_t shaded = 0, lit = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const gpu::float3 p = rgbAt(gbuffer.position, x, y);
            if (gbuffer.normal.at("A", x, y) == 0.0f || p.y > 1e-3f) {
                continue; // not the floor
            }
            const float reflected = unshadowed(harness.renderer().lights(), gbuffer, x, y).reflected.x;
            ASSERT_GT(reflected, 0.0f) << x << "," << y;
            const float visibility = direct.at("R", x, y) / reflected;
            if (p.z < 0.45f) { // in the wall's shadow, the PCF's blur (two texels) away from its edge
                EXPECT_LT(visibility, 1e-3f) << "floor at z = " << p.z << " (pixel " << x << "," << y << ")";
                ++shaded;
            } else if (p.z > 0.6f) {
                EXPECT_GT(visibility, 0.999f) << "floor at z = " << p.z << " (pixel " << x << "," << y << ")";
                ++lit;
            }
        }
    }
    EXPECT_GT(shaded, kSize * 10u) << "the view shows the shaded strip";
    EXPECT_GT(lit, kSize * 10u) << "and the lit floor beyond it";
}

// sunlit_rooms' camera sees only the shaded room, which the sun reaches nowhere (the path tracer's
// direct light there is zero). At 256 x 256 with the low preset's 1024-texel sun map, floor
// pixels at the foot of the south wall read the sun while the depth bias of a receiver compared
// with its own plane was a tenth of a texel (three here on lavapipe, two on the H200, where one
// read 4.1 against the reference's 0.08 and they carried 80 % of lumen's error; docs/deferred.md,
// "Shadows"); at 128 x 128 no pixel falls there.
TEST_P(DeferredGpuTest, TheSunReachesNoPixelOfTheSunlitRoomsShadedRoom) {
    constexpr uint32_t kRoomSize = 256;
    for (const uint32_t sunMap : {1024u, 2048u}) {
        DeferredHarness harness(device(), shaders(), scene::loadScene("sunlit_rooms"), kRoomSize, kRoomSize,
                                nullptr, sunMap);
        harness.render();
        const image::Image direct = harness.read(harness.renderer().direct());
        uint32_t sunlit = 0;
        for (uint32_t y = 0; y < kRoomSize; ++y) {
            for (uint32_t x = 0; x < kRoomSize; ++x) {
                const gpu::float3 c = rgbAt(direct, x, y);
                if (c.x + c.y + c.z > 0.0f && ++sunlit <= 4) {
                    ADD_FAILURE() << "sun map " << sunMap << ": pixel " << x << "," << y << " reads " << c.x;
                }
            }
        }
        EXPECT_EQ(sunlit, 0u) << "sun map " << sunMap;
    }
}

TEST_P(DeferredGpuTest, LightsBeyondTheShadowBudgetLightUnshadowedAndSaySo) {
    scene::Scene scene = scene::loadScene("cornell_box_point");
    const scene::Light original = scene.lights[0];
    for (int i = 0; i < 5; ++i) {
        scene::Light extra = original;
        extra.name = "extra " + std::to_string(i);
        extra.intensity *= 0.1f;
        extra.position += glm::vec3(-200.0f + 100.0f * float(i), -150.0f, 0.0f);
        scene.lights.push_back(extra);
    }
    scene::Light spot = original;
    spot.type = scene::LightType::Spot;
    spot.name = "spot";
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.outerConeAngle = 0.5f;
    scene.lights.push_back(spot);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.intensity = 0.1f;
    sun.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.5f));
    scene.lights.push_back(sun);

    DeferredHarness harness(device(), shaders(), scene, 32, 32);
    const auto frame = harness.render();
    EXPECT_TRUE(frame.ran("point shadows"));
    EXPECT_TRUE(frame.ran("sun shadow"));
    EXPECT_EQ(harness.renderer().pointShadowCubes(), 4u);
    ASSERT_EQ(harness.log().size(), 3u);
    for (const std::string& line : harness.log()) {
        EXPECT_NE(line.find("unshadowed"), std::string::npos) << line;
    }
    EXPECT_NE(harness.log().back().find("spot light 6 'spot'"), std::string::npos) << harness.log().back();
    const image::Image direct = harness.read(harness.renderer().direct());
    for (uint32_t y = 0; y < 32; ++y) {
        for (uint32_t x = 0; x < 32; ++x) {
            const gpu::float3 c = rgbAt(direct, x, y);
            ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << x << "," << y;
        }
    }
}

TEST_P(DeferredGpuTest, EmissiveSurfacesShowTheirRadiance) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box"), kSize, kSize);
    const auto frame = harness.render();
    EXPECT_EQ(frame.skipReason("point shadows"), "no point or spot lights");
    const image::Image material = harness.read(harness.renderer().gbuffer().material);
    const image::Image direct = harness.read(harness.renderer().direct());
    uint32_t emissive = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const gpu::float3 emission = rgbAt(material, x, y);
            if (emission.x > 0.0f) {
                ++emissive;
                EXPECT_EQ(emission, gpu::float3(17.0f, 12.0f, 4.0f)) << x << "," << y;
                // The light's material is black: what it shows is its emission alone.
                const gpu::float3 shown = rgbAt(direct, x, y);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(shown[c], emission[c], emission[c] * 1e-3f) << x << "," << y;
                }
            }
        }
    }
    EXPECT_GT(emissive, 4u); // the light quad on the ceiling is in view
}

// Three quads side by side in front of the camera: a single-sided quad facing away (culled),
// the same mesh mirrored by an x-flip that still faces the camera (drawn: its winding flips,
// so it culls front faces), and a double-sided quad facing away (drawn, normal towards us).
TEST_P(DeferredGpuTest, MirroredAndDoubleSidedInstancesCullTheRightFaces) {
    scene::Scene scene;
    scene.name = "culling";
    scene.materials = {{.name = "single", .baseColor = {0.5f, 0.5f, 0.5f, 1.0f}},
                       {.name = "double", .baseColor = {0.25f, 0.5f, 0.75f, 1.0f}, .doubleSided = true}};
    scene::MeshBuilder toward("toward");
    toward.quad({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}); // front +z, towards the camera
    scene::MeshBuilder away("away");
    away.quad({-1, -1, 0}, {-1, 1, 0}, {1, 1, 0}, {1, -1, 0}); // front -z
    scene.meshes = {toward.finish(), away.finish()};
    scene.meshes[1].submeshes[0].material = 0;
    scene.meshes.push_back(scene.meshes[1]);
    scene.meshes[2].submeshes[0].material = 1;
    auto at = [](float x) { return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)); };
    scene.instances = {
        {.mesh = 1, .transform = at(-2.5f), .name = "culled"},
        {.mesh = 0, .transform = glm::scale(at(0.0f), glm::vec3(-1, 1, 1)), .name = "mirrored"},
        {.mesh = 2, .transform = at(2.5f), .name = "double-sided"}};
    scene.lights.push_back({.type = scene::LightType::Directional, .name = "sun", .direction = {0, 0, -1}});
    scene.camera = {.name = "camera",
                    .position = {0, 0, 8},
                    .forward = {0, 0, -1},
                    .up = {0, 1, 0},
                    .fovY = 0.6f,
                    .nearPlane = 0.1f,
                    .farPlane = 100.0f};
    scene.image = {96, 32};

    DeferredHarness harness(device(), shaders(), scene, 96, 32);
    harness.render();
    const image::Image normal = harness.read(harness.renderer().gbuffer().normal);
    const image::Image direct = harness.read(harness.renderer().direct());
    // Column centres of the three quads at y = 16.
    // The camera sees +-tan(0.3) x 8 x 3 = 7.4 units across 96 pixels: 2.5 units is 16 pixels.
    const uint32_t culled = 48 - 16, mirrored = 48, doubleSided = 48 + 16;
    EXPECT_EQ(normal.at("A", culled, 16), 0.0f) << "a single-sided back face is culled";
    ASSERT_EQ(normal.at("A", mirrored, 16), 1.0f) << "the mirrored instance is drawn";
    EXPECT_NEAR(normal.at("B", mirrored, 16), 1.0f, 1e-3f);
    ASSERT_EQ(normal.at("A", doubleSided, 16), 1.0f) << "a double-sided back face is drawn";
    EXPECT_NEAR(normal.at("B", doubleSided, 16), 1.0f, 1e-3f) << "with its normal turned to the viewer";
    // Sun from behind the camera (travelling -z): both visible quads are lit head-on.
    EXPECT_NEAR(direct.at("R", mirrored, 16), 0.5f / std::numbers::pi_v<float>, 1e-3f);
    EXPECT_NEAR(direct.at("B", doubleSided, 16), 0.75f / std::numbers::pi_v<float>, 1e-3f);
}

TEST_P(DeferredGpuTest, PointShadowMapsFollowTheApiCubeConvention) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 16, 16);
    harness.render();
    const rhi::TextureHandle cubes = harness.renderer().pointShadowMaps();
    ASSERT_TRUE(cubes);
    constexpr uint32_t kCount = 4096;
    std::mt19937 random(11);
    std::normal_distribution<float> gauss;
    std::vector<gpu::float4> directions(kCount);
    for (gpu::float4& d : directions) {
        d = gpu::float4(gauss(random), gauss(random), gauss(random), 0.0f);
    }
    rhi::BufferHandle directionBuffer = rhi::createBufferWithData(
        device(),
        {.structStride = sizeof(gpu::float4), .usage = rhi::BufferUsage::Structured, .debugName = "dirs"},
        directions.data(), kCount * sizeof(gpu::float4));
    rhi::BufferHandle results =
        device().createBuffer({.size = kCount * sizeof(gpu::float4),
                               .structStride = sizeof(gpu::float4),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "lookups"});
    rhi::SamplerHandle point = device().createSampler({.minFilter = rhi::Filter::Point,
                                                       .magFilter = rhi::Filter::Point,
                                                       .mipFilter = rhi::Filter::Point,
                                                       .debugName = "point"});
    rhi::ShaderLibrary& library = shaders();
    gi::PipelineCache pipelines(device(), library);
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    gi::FrameContext frame(pipelines, *list, 0);
    rhi::BindingSetItem layers = rhi::BindingSetItem::sampledTexture(1, cubes);
    layers.overrideDimension = true;
    layers.viewDimension = rhi::TextureDimension::Texture2DArray;
    const uint32_t faceSize = cubes->desc().width;
    frame.compute("cube lookup", "deferred/cube_lookup_test")
        .constants(gpu::uint4(kCount, 0u, faceSize, 0u))
        .read(0, cubes)
        .bind(layers)
        .read(2, directionBuffer)
        .sampler(0, point)
        .write(0, results)
        .dispatchThreads(kCount, 1, 1, {LUMINA_LINEAR_GROUP_SIZE, 1, 1});
    list->end();
    submitAndWait(*list);
    const auto values = readBack<gpu::float4>(*results);
    uint32_t same = 0;
    for (uint32_t i = 0; i < kCount; ++i) {
        same += values[i].x == values[i].y ? 1 : 0;
        // Off by at most a texel where the two round a texel boundary differently.
        EXPECT_NEAR(values[i].x, values[i].y, 0.02f) << "direction " << i << " face " << values[i].z;
    }
    EXPECT_GT(same, kCount * 99 / 100);
}

TEST_P(DeferredGpuTest, CompositeAddsIndirectTimesAlbedoAndTonemaps) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 32, 32);
    rhi::TextureHandle indirect =
        device().createTexture({.format = rhi::Format::RGBA16_FLOAT,
                                .width = 32,
                                .height = 32,
                                .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                .debugName = "test indirect"});
    rhi::CommandListHandle clear = device().createCommandList();
    clear->begin();
    clear->clearColor(*indirect, {0.5f, 0.25f, 1.0f, 1.0f});
    clear->end();
    submitAndWait(*clear);
    harness.renderer().setIndirect(indirect);
    harness.renderer().setExposure(1.0f);
    harness.render();
    const image::Image direct = harness.read(harness.renderer().direct());
    const image::Image albedo = harness.read(harness.renderer().gbuffer().albedo);
    const image::Image hdr = harness.read(harness.renderer().hdr());
    const image::Image ldr = harness.read(harness.renderer().ldr());
    const image::Image display = image::toDisplay(hdr, {.exposureEv = 1.0f});
    const gpu::float3 indirectValue(0.5f, 0.25f, 1.0f);
    for (uint32_t y = 0; y < 32; ++y) {
        for (uint32_t x = 0; x < 32; ++x) {
            const gpu::float3 expected = rgbAt(direct, x, y) + indirectValue * rgbAt(albedo, x, y);
            const gpu::float3 got = rgbAt(hdr, x, y);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(got[c], expected[c], 2e-3f * expected[c] + 1e-6f)
                    << x << "," << y << " hdr " << c;
                EXPECT_NEAR(rgbAt(ldr, x, y)[c], rgbAt(display, x, y)[c], 1.0f / 255.0f) << x << "," << y;
            }
        }
    }
}

TEST_P(DeferredGpuTest, DumpWritesEveryIntermediateBuffer) {
    DeferredHarness harness(device(), shaders(), scene::loadScene("cornell_box_point"), 16, 16);
    harness.render();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("lumina_deferred_dump_" + std::to_string(std::random_device()()));
    const auto written = gi::dumpDeferredBuffers(device(), harness.renderer(), dir, {});
    for (const char* name : {"gbuffer_albedo.exr", "gbuffer_normal.exr", "gbuffer_material.exr",
                             "gbuffer_position.exr", "gbuffer_depth.exr", "point_shadow_0.exr",
                             "point_shadow_0.png", "direct.exr", "hdr.exr", "ldr.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    }
    EXPECT_EQ(image::readExrInfo(dir / "point_shadow_0.exr").width, 6u * 512u); // six faces side by side
    std::filesystem::remove_all(dir);
}

LUMINA_INSTANTIATE_GPU_TEST(DeferredGpuTest);

} // namespace
} // namespace lumina::test
