// Card capture (gi/surface_cache/card_capture_pass.h) of a known mesh: a floor of two
// coloured quads with a two-coloured lid above it. The lid hides part of the floor from +Y,
// so the mesh gets two +Y cards (mesh_cards.h); each capture must show exactly its own layer,
// in the right place and orientation, and leave the rest of the atlas untouched.
#include "gi/core/pipeline_cache.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/mesh_builder.h"
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/card_capture_pass.h"
#include "gi/surface_cache/surface_cards.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

class SurfaceCacheCaptureGpu : public GpuTest {};

enum Material : uint32_t { kRed, kGreen, kBlue, kYellow };
const glm::vec3 kAlbedo[] = {{0.8f, 0.2f, 0.1f}, {0.1f, 0.7f, 0.2f}, {0.1f, 0.2f, 0.9f}, {0.9f, 0.9f, 0.1f}};
const glm::vec3 kBlueEmission{0.0f, 0.0f, 2.0f};

// A quad facing +y at height y over [x0, x1] x [z0, z1].
void upQuad(scene::MeshBuilder& b, float y, float x0, float x1, float z0, float z1) {
    b.quad({x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0});
}

scene::Scene captureScene() {
    scene::Scene s;
    s.name = "card capture";
    for (uint32_t m = 0; m < 4; ++m) {
        s.materials.push_back(
            {.name = "material " + std::to_string(m), .baseColor = glm::vec4(kAlbedo[m], 1.0f)});
    }
    s.materials[kBlue].emission = kBlueEmission;
    scene::MeshBuilder b("floor and lid");
    b.material(kRed);
    upQuad(b, 0.0f, 0.0f, 1.0f, 0.0f, 2.0f); // floor, x < 1
    b.material(kGreen);
    upQuad(b, 0.0f, 1.0f, 2.0f, 0.0f, 2.0f); // floor, x > 1
    b.material(kBlue);
    upQuad(b, 0.5f, 0.5f, 1.5f, 0.5f, 1.0f); // lid, z < 1
    b.material(kYellow);
    upQuad(b, 0.5f, 0.5f, 1.5f, 1.0f, 1.5f); // lid, z > 1
    s.meshes.push_back(b.finish());
    // Moved, so that the capture must go through the instance transform.
    s.instances.push_back({.mesh = 0,
                           .transform = glm::translate(glm::mat4(1.0f), {5.0f, 1.0f, -3.0f}),
                           .name = "floor and lid"});
    scene::finishCamera(s);
    return s;
}

struct Texel {
    glm::vec4 albedo, normal, material;
};

class AtlasImages {
public:
    AtlasImages(rhi::IDevice& device, const SurfaceCacheAtlas& atlas) : size_(atlas.size()) {
        albedo_ = rhi::readTexture(device, *atlas.layer(AtlasLayer::Albedo).texture,
                                   {0, atlas.layer(AtlasLayer::Albedo).arrayLayer});
        normal_ = rhi::readTexture(device, *atlas.layer(AtlasLayer::Normal).texture,
                                   {0, atlas.layer(AtlasLayer::Normal).arrayLayer});
        material_ = rhi::readTexture(device, *atlas.layer(AtlasLayer::Material).texture,
                                     {0, atlas.layer(AtlasLayer::Material).arrayLayer});
    }
    Texel at(uint32_t x, uint32_t y) const {
        const size_t i = size_t(y) * size_ + x;
        Texel t;
        for (int c = 0; c < 4; ++c) {
            t.albedo[c] = half(albedo_, i, c);
            t.normal[c] = half(normal_, i, c);
            t.material[c] = half(material_, i, c);
        }
        return t;
    }

private:
    static float half(const std::vector<uint8_t>& bytes, size_t texel, int channel) {
        const size_t at = 8 * texel + 2 * size_t(channel);
        return glm::unpackHalf1x16(uint16_t(bytes[at] | (bytes[at + 1] << 8)));
    }
    uint32_t size_;
    std::vector<uint8_t> albedo_, normal_, material_;
};

void expectSurface(const Texel& t, Material m, const std::string& where) {
    for (int c = 0; c < 3; ++c) {
        // Dithered to one of the two halves around it: within one half-float step (2^-11 below 1).
        EXPECT_NEAR(t.albedo[c], kAlbedo[m][c], 1.0f / 2048.0f) << where << " channel " << c;
    }
    EXPECT_EQ(t.albedo.a, 1.0f) << where;
    EXPECT_NEAR(t.normal.x, 0.0f, 1e-3f) << where;
    EXPECT_NEAR(t.normal.y, 1.0f, 1e-3f) << where;
    EXPECT_NEAR(t.normal.z, 0.0f, 1e-3f) << where;
    EXPECT_EQ(t.normal.a, 1.0f) << where;
    const glm::vec3 emission = m == kBlue ? kBlueEmission : glm::vec3(0.0f);
    EXPECT_EQ(glm::vec3(t.material), emission) << where;
    EXPECT_EQ(t.material.a, float(m)) << where;
}

TEST_P(SurfaceCacheCaptureGpu, CapturesEachLayerOfAKnownMeshIntoItsRectangle) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = captureScene();
    SurfaceCacheSettings settings;
    settings.atlasSize = 256;
    settings.texelsPerUnit = 56.0f; // the lid (1 unit, padded 60 texels) takes 4 tiles across, the floor 7
    SurfaceCards cards(scene, settings);
    ASSERT_EQ(cards.cards().size(), 2u);
    const gpu::SurfaceCard& lid = cards.cards()[0]; // front layer first
    const gpu::SurfaceCard& floor = cards.cards()[1];
    ASSERT_NEAR(lid.boundsMinAndFlags.y, 1.5f - paddingUnits(settings), 1e-5f);
    ASSERT_EQ(lid.atlasRect.z, 4 * kTileSize);
    ASSERT_EQ(floor.atlasRect.z, 7 * kTileSize);

    gi::GpuScene gpuScene(device(), scene);
    SurfaceCacheAtlas atlas(device(), settings);
    CardCapturePass capture(device(), scene, gpuScene, atlas);
    rhi::BufferHandle cardBuffer =
        rhi::createBufferWithData(device(),
                                  {.size = cards.cards().size() * sizeof(gpu::SurfaceCard),
                                   .structStride = sizeof(gpu::SurfaceCard),
                                   .usage = rhi::BufferUsage::Structured,
                                   .debugName = "surface cards"},
                                  cards.cards().data(), cards.cards().size() * sizeof(gpu::SurfaceCard));
    gi::PipelineCache pipelines(device(), shaders());
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    atlas.recordClear(*list);
    gi::FrameContext frame(pipelines, *list, 0);
    const std::vector<uint32_t> dirty = cards.dirtyCards();
    ASSERT_EQ(dirty.size(), 2u);
    capture.record(frame, atlas, cardBuffer, cards.cards(), dirty);
    list->end();
    submitAndWait(*list);

    const AtlasImages images(device(), atlas);
    const auto inRect = [](const gpu::SurfaceCard& c, uint32_t x, uint32_t y) {
        return x >= c.atlasRect.x && x < c.atlasRect.x + c.atlasRect.z && y >= c.atlasRect.y &&
               y < c.atlasRect.y + c.atlasRect.w;
    };
    uint32_t checked = 0;
    for (uint32_t y = 0; y < atlas.size(); ++y) {
        for (uint32_t x = 0; x < atlas.size(); ++x) {
            const Texel t = images.at(x, y);
            const std::string where = "texel " + std::to_string(x) + ", " + std::to_string(y);
            if (!inRect(lid, x, y) && !inRect(floor, x, y)) {
                ASSERT_EQ(t.albedo, glm::vec4(0.0f)) << where << ": outside every card";
                ASSERT_EQ(t.normal, glm::vec4(0.0f)) << where;
                continue;
            }
            const gpu::SurfaceCard& card = inRect(lid, x, y) ? lid : floor;
            // +Y cards: u along +z, v along +x (mesh_cards.h), 64 texels over the card.
            const float u = (float(x - card.atlasRect.x) + 0.5f) / float(card.atlasRect.z);
            const float v = (float(y - card.atlasRect.y) + 0.5f) / float(card.atlasRect.w);
            if (std::abs(u - 0.5f) < 1.5f / 64.0f || std::abs(v - 0.5f) < 1.5f / 64.0f) {
                continue; // texels on a seam between two materials
            }
            if (&card == &lid) {
                expectSurface(t, u < 0.5f ? kBlue : kYellow, where + " (lid)");
            } else {
                // Red for x < 1, green beyond; never the lid above, which the slab clips away.
                expectSurface(t, v < 0.5f ? kRed : kGreen, where + " (floor)");
            }
            ++checked;
            if (::testing::Test::HasFailure()) {
                return;
            }
        }
    }
    EXPECT_GT(checked, 2u * 60u * 60u);
}

TEST_P(SurfaceCacheCaptureGpu, CapturesTheCornellBox) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = scene::loadScene("cornell_box");
    SurfaceCacheSettings settings;
    settings.atlasSize = 1024;
    settings.texelsPerUnit = 0.25f; // 4 mm texels: a wall takes 9 x 9 tiles
    SurfaceCards cards(scene, settings);
    gi::GpuScene gpuScene(device(), scene);
    SurfaceCacheAtlas atlas(device(), settings);
    CardCapturePass capture(device(), scene, gpuScene, atlas);
    rhi::BufferHandle cardBuffer =
        rhi::createBufferWithData(device(),
                                  {.size = cards.cards().size() * sizeof(gpu::SurfaceCard),
                                   .structStride = sizeof(gpu::SurfaceCard),
                                   .usage = rhi::BufferUsage::Structured,
                                   .debugName = "surface cards"},
                                  cards.cards().data(), cards.cards().size() * sizeof(gpu::SurfaceCard));
    gi::PipelineCache pipelines(device(), shaders());
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    atlas.recordClear(*list);
    gi::FrameContext frame(pipelines, *list, 0);
    capture.record(frame, atlas, cardBuffer, cards.cards(), cards.dirtyCards());
    list->end();
    submitAndWait(*list);
    const AtlasImages images(device(), atlas);

    std::vector<uint32_t> owner(size_t(atlas.size()) * atlas.size(), LUMINA_NO_CARD);
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        const glm::uvec4 r = cards.cards()[c].atlasRect;
        for (uint32_t y = r.y; y < r.y + r.w; ++y) {
            std::fill_n(owner.begin() + size_t(y) * atlas.size() + r.x, r.z, c);
        }
    }
    std::vector<uint32_t> covered(cards.cards().size(), 0), own(cards.cards().size(), 0);
    std::vector<glm::dvec3> albedoSum(scene.materials.size(), glm::dvec3(0.0));
    std::vector<uint32_t> albedoCount(scene.materials.size(), 0);
    for (uint32_t y = 0; y < atlas.size(); ++y) {
        for (uint32_t x = 0; x < atlas.size(); ++x) {
            const Texel t = images.at(x, y);
            const uint32_t c = owner[size_t(y) * atlas.size() + x];
            if (t.normal.a == 0.0f) {
                continue;
            }
            const std::string where = "texel " + std::to_string(x) + ", " + std::to_string(y);
            ASSERT_NE(c, LUMINA_NO_CARD) << where << ": written outside every card";
            ++covered[c];
            // The texel's albedo is its material's, and its normal faces the card.
            const uint32_t m = uint32_t(t.material.a);
            ASSERT_LT(m, scene.materials.size()) << where;
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_NEAR(t.albedo[ch], scene.materials[m].baseColor[ch], 1.0f / 2048.0f) << where;
                albedoSum[m][ch] += t.albedo[ch];
            }
            ++albedoCount[m];
            ASSERT_GT(glm::dot(glm::vec3(t.normal), glm::vec3(cards.cards()[c].normalAndPadding)), 0.0f)
                << where;
            ASSERT_EQ(glm::vec3(t.material), scene.materials[m].emission) << where;
            const scene::Instance& instance = scene.instances[cards.instanceOf(c)];
            own[c] += m == scene.meshes[instance.mesh].submeshes[0].material;
        }
    }
    // The dither keeps each material's albedo right on average (docs/surface_cache.md): the mean
    // over its texels is within a twentieth of a half step of the material's.
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        for (int ch = 0; ch < 3 && albedoCount[m] > 1000; ++ch) {
            EXPECT_NEAR(albedoSum[m][ch] / albedoCount[m], scene.materials[m].baseColor[ch],
                        1.0 / 2048.0 / 20.0)
                << scene.materials[m].name << " channel " << ch;
        }
    }
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        const glm::uvec4 r = cards.cards()[c].atlasRect;
        const float coverage = float(covered[c]) / float(r.z * r.w);
        // Quads fill their cards up to the slant of their published corners; the blocks' tops,
        // turned 17 degrees in their axis-aligned cards, about two thirds.
        EXPECT_GT(coverage, 0.5f) << cards.describe(c);
        // Only the card's own instance is captured (the light quad 0.1 mm below the ceiling has
        // a card of its own).
        EXPECT_EQ(own[c], covered[c]) << cards.describe(c);
    }

    // ... but other instances hide what they cover within its slab: the ceiling's down-facing
    // card is empty where the light hangs under it, and captured around it.
    const auto instanceNamed = [&](const std::string& name) {
        for (uint32_t i = 0; i < scene.instances.size(); ++i) {
            if (scene.instances[i].name == name) {
                return i;
            }
        }
        throw std::runtime_error("no instance " + name);
    };
    const uint32_t ceiling = instanceNamed("ceiling");
    const auto texelOf = [&](const gpu::SurfaceCard& card, glm::vec3 world) {
        const glm::vec4 p(world, 1.0f);
        const glm::vec2 uv(glm::dot(card.worldToCard0, p), glm::dot(card.worldToCard1, p));
        return glm::uvec2(glm::vec2(card.atlasRect.x, card.atlasRect.y) +
                          uv * glm::vec2(card.atlasRect.z, card.atlasRect.w));
    };
    int downCards = 0;
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        const gpu::SurfaceCard& card = cards.cards()[c];
        if (cards.instanceOf(c) != ceiling || card.normalAndPadding.y > -0.9f) {
            continue;
        }
        ++downCards;
        const glm::uvec2 underLight = texelOf(card, {278.0f, 548.8f, 279.5f});
        const glm::uvec2 beside = texelOf(card, {278.0f, 548.8f, 400.0f});
        EXPECT_EQ(images.at(underLight.x, underLight.y).albedo.a, 0.0f)
            << "hidden by the light: " << cards.describe(c);
        EXPECT_EQ(images.at(beside.x, beside.y).albedo.a, 1.0f) << "beside the light: " << cards.describe(c);
    }
    EXPECT_EQ(downCards, 1);
}

TEST_P(SurfaceCacheCaptureGpu, ACardOutsideTheAtlasIsRefused) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = captureScene();
    SurfaceCacheSettings settings;
    settings.atlasSize = 128;
    settings.texelsPerUnit = 16.0f;
    SurfaceCards cards(scene, settings);
    std::vector<gpu::SurfaceCard> broken = cards.cards();
    broken[1].atlasRect.x = 128;
    gi::GpuScene gpuScene(device(), scene);
    SurfaceCacheAtlas atlas(device(), settings);
    CardCapturePass capture(device(), scene, gpuScene, atlas);
    gi::PipelineCache pipelines(device(), shaders());
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    gi::FrameContext frame(pipelines, *list, 0);
    const std::vector<uint32_t> which = {1};
    EXPECT_THROW(capture.record(frame, atlas, nullptr, broken, which), std::invalid_argument);
    const std::vector<uint32_t> missing = {7};
    EXPECT_THROW(capture.record(frame, atlas, nullptr, broken, missing), std::out_of_range);
    list->end();
}

LUMINA_INSTANTIATE_GPU_TEST(SurfaceCacheCaptureGpu);

} // namespace
} // namespace lumina::test
