// SurfaceCards under random instance moves in a small atlas: cards follow their instances,
// atlas rectangles never overlap and always match the allocator's owner map, a crowded atlas is
// defragmented (moving other cards, which become DIRTY), and a move that cannot fit degrades the
// card to a coarser level or evicts it instead of failing. A move recaptures the other cards the instance
// covered or now covers.
#include "gi/scene/mesh_builder.h"
#include "gi/surface_cache/surface_cards.h"

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace lumina::surface_cache {
namespace {

constexpr uint32_t kInstances = 10;

scene::Scene quads() {
    scene::Scene s;
    s.name = "quads";
    s.materials = {scene::Material{.name = "white"}};
    scene::MeshBuilder b("unit quad");
    b.quad({0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {0, 0, 0}); // facing +y
    s.meshes.push_back(b.finish());
    for (uint32_t i = 0; i < kInstances; ++i) {
        s.instances.push_back({.mesh = 0,
                               .transform = glm::translate(glm::mat4(1.0f), {10.0f * float(i), 0.0f, 0.0f}),
                               .name = "quad " + std::to_string(i)});
    }
    return s;
}

bool sameCards(const std::vector<gpu::SurfaceCard>& a, const std::vector<gpu::SurfaceCard>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::SurfaceCard)) == 0;
}

void expectAtlasConsistent(const SurfaceCards& cards) {
    const TileAllocator& atlas = cards.atlas();
    std::vector<uint32_t> owners(size_t(atlas.tilesX()) * atlas.tilesY(), kNoOwner);
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        const glm::uvec4 r = cards.cards()[c].atlasRect / kTileSize;
        for (uint32_t y = r.y; y < r.y + r.w; ++y) {
            for (uint32_t x = r.x; x < r.x + r.z; ++x) {
                ASSERT_LT(x, atlas.tilesX());
                ASSERT_LT(y, atlas.tilesY());
                ASSERT_EQ(owners[size_t(y) * atlas.tilesX() + x], kNoOwner)
                    << "cards overlap at " << x << ", " << y;
                owners[size_t(y) * atlas.tilesX() + x] = c;
            }
        }
    }
    for (uint32_t y = 0; y < atlas.tilesY(); ++y) {
        for (uint32_t x = 0; x < atlas.tilesX(); ++x) {
            ASSERT_EQ(atlas.owner(x, y), owners[size_t(y) * atlas.tilesX() + x]) << x << ", " << y;
        }
    }
    ASSERT_EQ(atlas.ownerTable(), owners);
}

TEST(SurfaceCacheCards, RandomMovesKeepTheAtlasConsistentDefragmentAndDegrade) {
    const scene::Scene scene = quads();
    SurfaceCacheSettings settings;
    settings.atlasSize = 8 * kTileSize; // 8 x 8 tiles
    settings.texelsPerUnit = kTileSize; // a quad scaled by s takes ceil(s) x ceil(s) tiles
    SurfaceCards cards(scene, settings);
    ASSERT_EQ(cards.cards().size(), kInstances);
    std::mt19937 rng(5);
    const float scales[] = {0.5f, 0.5f, 1.5f, 1.5f, 2.5f, 3.5f};
    uint32_t defragments = 0, degraded = 0, moves = 0;
    for (int step = 0; step < 400; ++step) {
        for (uint32_t c = 0; c < cards.cards().size(); ++c) {
            cards.markCaptured(c, uint32_t(step));
        }
        const uint32_t instance = rng() % kInstances;
        const float s = scales[rng() % std::size(scales)];
        const glm::mat4 transform = glm::translate(glm::mat4(1.0f), {10.0f * float(instance), 1.0f, 0.0f}) *
                                    glm::scale(glm::mat4(1.0f), {s, 1.0f, s});
        const std::vector<gpu::SurfaceCard> before = cards.cards();
        const uint8_t levelBefore = cards.level(instance);
        cards.moveInstance(instance, transform, scene.lights); // a full atlas never throws
        ++moves;
        const gpu::SurfaceCard& moved = cards.cards()[instance];
        const uint32_t tiles = uint32_t(std::ceil(s));
        EXPECT_EQ(cards.fullTiles(instance), glm::uvec2(tiles));
        if (cards.level(instance) == kCardEvicted) {
            // No room at any level: no texels, not VISIBLE (its hits read the voxel lighting).
            EXPECT_EQ(moved.atlasRect, glm::uvec4(0u));
            EXPECT_EQ(gpu::asuint(moved.boundsMinAndFlags.w), LUMINA_CARD_DIRTY | LUMINA_CARD_DYNAMIC);
            degraded += levelBefore != kCardEvicted;
        } else {
            // Its level, or a coarser one where the atlas had no room.
            EXPECT_GE(cards.level(instance), levelBefore == kCardEvicted ? 0 : levelBefore);
            const glm::uvec2 expected = tilesAtLevel(tiles, tiles, cards.level(instance));
            EXPECT_EQ(moved.atlasRect.z, expected.x * kTileSize);
            EXPECT_EQ(moved.atlasRect.w, expected.y * kTileSize);
            EXPECT_EQ(gpu::asuint(moved.boundsMinAndFlags.w),
                      LUMINA_CARD_VISIBLE | LUMINA_CARD_DIRTY | LUMINA_CARD_DYNAMIC);
            degraded += levelBefore != kCardEvicted && cards.level(instance) > levelBefore;
        }
        EXPECT_NEAR(moved.boundsMaxAndInstance.x, 10.0f * float(instance) + s + paddingUnits(settings),
                    1e-4f);
        bool defragmented = false;
        for (uint32_t c = 0; c < kInstances; ++c) {
            if (c == instance) {
                continue;
            }
            const bool rectMoved = before[c].atlasRect != cards.cards()[c].atlasRect;
            const bool dirty = (gpu::asuint(cards.cards()[c].boundsMinAndFlags.w) & LUMINA_CARD_DIRTY) != 0;
            EXPECT_EQ(rectMoved, dirty) << "card " << c << ": moved texels must be captured again";
            EXPECT_EQ(before[c].atlasRect.z, cards.cards()[c].atlasRect.z);
            defragmented = defragmented || rectMoved;
        }
        defragments += defragmented;
        expectAtlasConsistent(cards);
        if (::testing::Test::HasFailure()) {
            return;
        }
    }
    // The sequence exercised every path.
    EXPECT_GT(moves, 100u);
    EXPECT_GT(defragments, 0u);
    EXPECT_GT(degraded, 0u);
}

TEST(SurfaceCacheCards, SingularMoveThrowsAndChangesNothing) {
    const scene::Scene scene = quads();
    SurfaceCards cards(scene);
    const std::vector<gpu::SurfaceCard> before = cards.cards();
    EXPECT_THROW(cards.moveInstance(3, glm::scale(glm::mat4(1.0f), {0.0f, 1.0f, 1.0f}), scene.lights),
                 std::invalid_argument);
    EXPECT_TRUE(sameCards(before, cards.cards()));
    EXPECT_THROW(cards.moveInstance(kInstances, glm::mat4(1.0f), scene.lights), std::out_of_range);
}

// A card's capture clears what other instances hide of it, so a move recaptures the cards the
// instance overlapped before and after it, and no others.
TEST(SurfaceCacheCards, AMoveRecapturesTheCardsTheInstanceCoveredOrNowCovers) {
    const scene::Scene scene = quads();
    SurfaceCards cards(scene);
    const auto dirtyAfter = [&](uint32_t instance, glm::vec3 to) {
        for (uint32_t c = 0; c < cards.cards().size(); ++c) {
            cards.markCaptured(c, 0);
        }
        cards.moveInstance(instance, glm::translate(glm::mat4(1.0f), to), scene.lights);
        return cards.dirtyCards();
    };
    // Quad 0 onto quad 1 (hovering just above it), then far away, then further still.
    EXPECT_EQ(dirtyAfter(0, {10.0f, 0.001f, 0.0f}), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(dirtyAfter(0, {200.0f, 0.0f, 0.0f}), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(dirtyAfter(0, {300.0f, 0.0f, 0.0f}), (std::vector<uint32_t>{0}));
}

} // namespace
} // namespace lumina::surface_cache
