// The cards of the built-in Cornell box: sane bounds and atlas rectangles, no overlap in the
// atlas, and every triangle of the scene owned (through the card BVH) by a card of its own mesh
// that faces the way it does. Also atlas overflow, light masks and moving an instance.
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/card_bvh.h"
#include "gi/surface_cache/surface_cards.h"
#include "tests/surface_cache/scene_triangles.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <numeric>

namespace lumina::surface_cache {
namespace {

uint32_t flagsOf(const gpu::SurfaceCard& card) {
    return gpu::asuint(card.boundsMinAndFlags.w);
}

class SurfaceCacheCornell : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new scene::Scene(scene::loadScene("cornell_box")); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static scene::Scene* scene_;
};
scene::Scene* SurfaceCacheCornell::scene_ = nullptr;

TEST_F(SurfaceCacheCornell, BoundsAndAtlasRectanglesAreSane) {
    const scene::Scene& scene = *scene_;
    const SurfaceCards cards(scene);
    // Walls, floor, ceiling and light are one-sided quads: one card each; the blocks have a top
    // and four sides (no bottom): five each.
    ASSERT_EQ(scene.instances.size(), 8u);
    uint32_t expected = 0;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const std::string& name = scene.instances[i].name;
        const uint32_t want = (name == "short block" || name == "tall block") ? 5u : 1u;
        EXPECT_EQ(cards.cardCount(i), want) << name;
        expected += want;
    }
    ASSERT_EQ(cards.cards().size(), expected);

    const scene::Bounds world = scene.worldBounds();
    const float pad = paddingUnits(cards.settings());
    const uint32_t atlasSize = cards.settings().atlasSize;
    for (uint32_t i = 0; i < cards.cards().size(); ++i) {
        SCOPED_TRACE(cards.describe(i));
        const gpu::SurfaceCard& card = cards.cards()[i];
        const glm::vec3 lo(card.boundsMinAndFlags), hi(card.boundsMaxAndInstance);
        EXPECT_TRUE(glm::all(glm::lessThan(lo, hi)));
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(lo, world.min - glm::vec3(pad * 1.001f))));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(hi, world.max + glm::vec3(pad * 1.001f))));
        EXPECT_EQ(card.normalAndPadding.w, pad);
        EXPECT_EQ(flagsOf(card), LUMINA_CARD_VISIBLE | LUMINA_CARD_DIRTY | LUMINA_CARD_STATIC);
        EXPECT_EQ(cards.instanceOf(i), gpu::asuint(card.boundsMaxAndInstance.w));
        // Atlas rectangle: whole tiles inside the atlas, sized from the card's world size.
        const glm::uvec4 r = card.atlasRect;
        EXPECT_EQ(r.x % kTileSize, 0u);
        EXPECT_EQ(r.y % kTileSize, 0u);
        EXPECT_GT(r.z, 0u);
        EXPECT_GT(r.w, 0u);
        EXPECT_EQ(r.z % kTileSize, 0u);
        EXPECT_EQ(r.w % kTileSize, 0u);
        EXPECT_LE(r.x + r.z, atlasSize);
        EXPECT_LE(r.y + r.w, atlasSize);
        // 1 texel per millimetre: a 550 mm wall (with padding) needs at most 576 texels a side.
        EXPECT_LE(r.z, 576u);
        EXPECT_LE(r.w, 576u);
        for (uint32_t y = r.y / kTileSize; y < (r.y + r.w) / kTileSize; ++y) {
            for (uint32_t x = r.x / kTileSize; x < (r.x + r.z) / kTileSize; ++x) {
                EXPECT_EQ(cards.atlas().owner(x, y), i);
            }
        }
    }
    // No two rectangles overlap.
    for (uint32_t a = 0; a < cards.cards().size(); ++a) {
        for (uint32_t b = a + 1; b < cards.cards().size(); ++b) {
            const glm::uvec4 ra = cards.cards()[a].atlasRect, rb = cards.cards()[b].atlasRect;
            const bool overlap =
                ra.x < rb.x + rb.z && rb.x < ra.x + ra.z && ra.y < rb.y + rb.w && rb.y < ra.y + ra.w;
            EXPECT_FALSE(overlap) << cards.describe(a) << " and " << cards.describe(b);
        }
    }
    // The floor card looks up (+Y), the ceiling's down, into the box.
    EXPECT_EQ(glm::vec3(cards.cards()[cards.firstCard(0)].normalAndPadding), glm::vec3(0, 1, 0));
    EXPECT_EQ(glm::vec3(cards.cards()[cards.firstCard(1)].normalAndPadding), glm::vec3(0, -1, 0));
}

TEST_F(SurfaceCacheCornell, EveryTriangleIsOwnedByACardOfItsMeshFacingItsWay) {
    const scene::Scene& scene = *scene_;
    const SurfaceCards cards(scene);
    const CardBvh bvh = buildCardBvh(cards.cards());
    uint32_t triangles = 0;
    for (const test::WorldTriangle& tri : test::worldTriangles(scene)) {
        const uint32_t i = tri.instance;
        const glm::vec3 a = tri.a, b = tri.b, c = tri.c, normal = tri.normal;
        // Sample points across the triangle, including near its corners.
        for (const glm::vec3 w : {glm::vec3(1, 1, 1) / 3.0f, glm::vec3(0.9f, 0.05f, 0.05f),
                                  glm::vec3(0.05f, 0.9f, 0.05f), glm::vec3(0.05f, 0.05f, 0.9f)}) {
            const glm::vec3 p = w.x * a + w.y * b + w.z * c;
            const CardOwner owner = findCardOwner(bvh, cards.cards(), p, normal);
            ASSERT_NE(owner.card, LUMINA_NO_CARD) << scene.instances[i].name;
            EXPECT_EQ(cards.instanceOf(owner.card), i)
                << scene.instances[i].name << " at " << p.x << ", " << p.y << ", " << p.z << " owned by "
                << cards.describe(owner.card);
            EXPECT_GT(glm::dot(glm::vec3(cards.cards()[owner.card].normalAndPadding), normal), 0.5f);
            // The point lies on the card: inside its (u, v) square and depth slab.
            const glm::vec3 local = gpu::worldToCardSpace(cards.cards()[owner.card], p);
            EXPECT_GE(local.x, -1e-4f);
            EXPECT_LE(local.x, 1.0f + 1e-4f);
            EXPECT_GE(local.y, -1e-4f);
            EXPECT_LE(local.y, 1.0f + 1e-4f);
            EXPECT_GT(local.z, 0.0f);
            EXPECT_LT(local.z, 1.0f);
        }
        ++triangles;
    }
    EXPECT_EQ(triangles, scene.triangleCount());
}

TEST_F(SurfaceCacheCornell, SdfHitsInFrontOfTheSurfaceFindTheirCards) {
    // Sphere tracing stops in front of the surface, up to about half a mesh-SDF voxel for open
    // meshes (about 4 mm here at 64 voxels over 560 mm): padding of 10 mm covers that.
    const scene::Scene& scene = *scene_;
    SurfaceCacheSettings settings;
    settings.minPaddingUnits = 10.0f;
    const SurfaceCards cards(scene, settings);
    EXPECT_EQ(paddingUnits(cards.settings()), 10.0f);
    const CardBvh bvh = buildCardBvh(cards.cards());
    for (const test::WorldTriangle& tri : test::worldTriangles(scene)) {
        const uint32_t i = tri.instance;
        const glm::vec3 a = tri.a, b = tri.b, c = tri.c, normal = tri.normal;
        for (float offset : {0.5f, 2.0f, 4.0f}) {
            const glm::vec3 p = 0.8f * a + 0.1f * b + 0.1f * c + offset * normal;
            const CardOwner owner = findCardOwner(bvh, cards.cards(), p, normal);
            ASSERT_NE(owner.card, LUMINA_NO_CARD) << scene.instances[i].name << " offset " << offset;
            EXPECT_EQ(cards.instanceOf(owner.card), i) << scene.instances[i].name << " offset " << offset
                                                       << " owned by " << cards.describe(owner.card);
        }
    }
}

// The degradation order when the cards do not fit at full density: coarser levels for the
// cards that look smallest from the viewer first, then eviction of the least useful; never an
// error. The viewer stands just above the floor's centre, so the floor is the most useful card.
TEST_F(SurfaceCacheCornell, AFullAtlasDegradesSmallestLookingCardsFirstThenEvicts) {
    const glm::vec3 viewer(278.0f, 20.0f, 280.0f);
    const auto build = [&](uint32_t atlasSize) {
        SurfaceCacheSettings settings;
        settings.atlasSize = atlasSize;
        settings.texelsPerUnit = 1.0f;
        return SurfaceCards(*scene_, settings, viewer);
    };
    // The plan is monotone (a more useful card is never coarser); the allocator may put a few
    // cards a level coarser where fragmentation leaves no block, so the test compares halves:
    // the more useful half is on average at least as fine as the less useful half.
    const auto expectMoreUsefulFiner = [](const SurfaceCards& cards) {
        std::vector<uint32_t> order(cards.cards().size());
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(),
                  [&](uint32_t a, uint32_t b) { return cards.priority(a) > cards.priority(b); });
        double useful = 0.0, rest = 0.0;
        const size_t half = order.size() / 2;
        for (size_t i = 0; i < order.size(); ++i) {
            (i < half ? useful : rest) += cards.level(order[i]);
        }
        EXPECT_LE(useful / double(half), rest / double(order.size() - half));
    };
    // Room for everything: full density.
    const SurfaceCards roomy = build(4096);
    EXPECT_EQ(roomy.occupancy().cardsAtLevel[0], roomy.cards().size());
    EXPECT_EQ(roomy.occupancy().evicted, 0u);

    // About half the room: some cards coarser, none evicted, the floor still at full density.
    const uint32_t floorCard = roomy.firstCard(0);
    ASSERT_EQ(scene_->instances[0].name, "floor");
    const SurfaceCards tight = build(1024);
    EXPECT_EQ(tight.occupancy().evicted, 0u);
    EXPECT_LT(tight.occupancy().cardsAtLevel[0], tight.cards().size());
    EXPECT_EQ(tight.level(floorCard), 0u);
    EXPECT_LE(tight.atlas().usedTiles(), tight.atlas().tilesX() * tight.atlas().tilesY());
    expectMoreUsefulFiner(tight);

    // Fewer tiles than cards: the least useful cards are evicted (no texels, not VISIBLE) and
    // every kept card is more useful than every evicted one.
    const SurfaceCards tiny = build(4 * kTileSize); // 16 tiles for 16 cards, 90% of them planned
    const AtlasOccupancy o = tiny.occupancy();
    EXPECT_GT(o.evicted, 0u);
    EXPECT_LT(o.evicted, tiny.cards().size());
    float lowestKept = INFINITY, highestEvicted = 0.0f;
    for (uint32_t c = 0; c < tiny.cards().size(); ++c) {
        const gpu::SurfaceCard& card = tiny.cards()[c];
        if (tiny.level(c) == kCardEvicted) {
            highestEvicted = std::max(highestEvicted, tiny.priority(c));
            EXPECT_EQ(card.atlasRect, glm::uvec4(0u)) << tiny.describe(c);
            EXPECT_EQ(flagsOf(card) & LUMINA_CARD_VISIBLE, 0u) << tiny.describe(c);
        } else {
            lowestKept = std::min(lowestKept, tiny.priority(c));
            EXPECT_EQ(flagsOf(card) & LUMINA_CARD_VISIBLE, LUMINA_CARD_VISIBLE) << tiny.describe(c);
        }
    }
    EXPECT_LT(highestEvicted, lowestKept);
    EXPECT_NE(tiny.level(floorCard), kCardEvicted);
    // Evicted cards are never captured.
    for (uint32_t c : tiny.dirtyCards()) {
        EXPECT_NE(tiny.level(c), kCardEvicted) << tiny.describe(c);
    }
}

TEST_F(SurfaceCacheCornell, LightMasksFollowTheLights) {
    const SurfaceCards area(*scene_);
    for (const gpu::SurfaceCard& card : area.cards()) {
        EXPECT_EQ(card.lightMask, glm::uvec4(0u)); // an emissive quad, no punctual light
    }
    scene::Scene point = scene::loadScene("cornell_box_point");
    ASSERT_EQ(point.lights.size(), 1u);
    point.lights[0].range = 200.0f; // reaches the ceiling (10 mm away), not the floor (539 mm)
    const SurfaceCards ranged(point);
    EXPECT_EQ(ranged.cards()[ranged.firstCard(1)].lightMask, glm::uvec4(1u, 0u, 0u, 0u));
    EXPECT_EQ(ranged.cards()[ranged.firstCard(0)].lightMask, glm::uvec4(0u));
    point.lights.resize(129, point.lights[0]);
    EXPECT_THROW(SurfaceCards{point}, std::invalid_argument);
}

TEST_F(SurfaceCacheCornell, MovingAnInstanceMovesItsCardsAndMarksThemDynamic) {
    SurfaceCards cards(*scene_);
    const uint32_t block = 5; // short block
    ASSERT_EQ(scene_->instances[block].name, "short block");
    const std::vector<gpu::SurfaceCard> before = cards.cards();
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        cards.markCaptured(c, 7);
    }
    EXPECT_TRUE(cards.dirtyCards().empty());
    const glm::mat4 moved = glm::translate(glm::mat4(1.0f), {10.0f, 0.0f, 0.0f});
    cards.moveInstance(block, moved, scene_->lights);
    const std::vector<uint32_t> dirty = cards.dirtyCards();
    // The block's cards, and the floor's, whose texels under the block the capture clears.
    const uint32_t floor = 0;
    ASSERT_EQ(scene_->instances[floor].name, "floor");
    std::vector<uint32_t> expected;
    for (uint32_t c = 0; c < cards.cards().size(); ++c) {
        const uint32_t owner = cards.instanceOf(c);
        if (owner == block || (owner == floor && cards.cards()[c].normalAndPadding.y > 0.9f)) {
            expected.push_back(c);
        }
    }
    for (uint32_t c : expected) {
        EXPECT_NE(std::find(dirty.begin(), dirty.end(), c), dirty.end())
            << cards.describe(c) << " is not dirty";
    }
    // Nothing the block's padded bounds do not reach: not the left wall, the ceiling or the light.
    for (uint32_t c : dirty) {
        const std::string& owner = scene_->instances[cards.instanceOf(c)].name;
        EXPECT_TRUE(owner != "left wall" && owner != "ceiling" && owner != "light")
            << cards.describe(c) << " made dirty";
    }
    for (uint32_t c = cards.firstCard(block); c < cards.firstCard(block) + cards.cardCount(block); ++c) {
        const gpu::SurfaceCard& card = cards.cards()[c];
        EXPECT_EQ(flagsOf(card), LUMINA_CARD_VISIBLE | LUMINA_CARD_DIRTY | LUMINA_CARD_DYNAMIC);
        EXPECT_NEAR(card.boundsMinAndFlags.x, before[c].boundsMinAndFlags.x + 10.0f, 1e-3f);
        EXPECT_EQ(card.atlasRect, before[c].atlasRect); // same size: same texels
        EXPECT_EQ(card.info.w, 7u);
    }
    // A scale that changes the size in tiles moves the card to a new rectangle.
    cards.moveInstance(block, glm::scale(glm::mat4(1.0f), {3.0f, 3.0f, 3.0f}), scene_->lights);
    const gpu::SurfaceCard& top = cards.cards()[cards.firstCard(block)];
    EXPECT_GT(top.atlasRect.z * top.atlasRect.w,
              before[cards.firstCard(block)].atlasRect.z * before[cards.firstCard(block)].atlasRect.w);
    EXPECT_EQ(cards.atlas().owner(top.atlasRect.x / kTileSize, top.atlasRect.y / kTileSize),
              cards.firstCard(block));
}

} // namespace
} // namespace lumina::surface_cache
