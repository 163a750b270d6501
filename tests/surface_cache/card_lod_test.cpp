// The card LOD: the planner (card_lod.h) and SurfaceCards::updateLod following a viewer.
#include "gi/scene/mesh_builder.h"
#include "gi/surface_cache/card_lod.h"
#include "gi/surface_cache/surface_cards.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lumina::surface_cache {
namespace {

constexpr uint32_t kMaxLevel = 4;

// n cards of 8x8 tiles in a row along x, one every 10 units; the viewer at x = 0.
std::vector<CardLodRequest> row(uint32_t n) {
    std::vector<CardLodRequest> cards(n);
    for (uint32_t i = 0; i < n; ++i) {
        cards[i].tilesX = cards[i].tilesY = 8;
        cards[i].bounds = {{10.0f * float(i), 0.0f, 0.0f}, {10.0f * float(i) + 4.0f, 4.0f, 0.1f}};
    }
    return cards;
}

std::vector<float> priorities(const std::vector<CardLodRequest>& cards, glm::vec3 viewer) {
    std::vector<float> p;
    for (const CardLodRequest& card : cards) {
        p.push_back(cardPriority(card.bounds, viewer));
    }
    return p;
}

uint64_t tilesOf(const std::vector<CardLodRequest>& cards, const CardLodPlan& plan) {
    uint64_t tiles = 0;
    for (size_t i = 0; i < cards.size(); ++i) {
        if (plan.levels[i] != kCardEvicted) {
            const glm::uvec2 t = tilesAtLevel(cards[i].tilesX, cards[i].tilesY, plan.levels[i]);
            tiles += uint64_t(t.x) * t.y;
        }
    }
    return tiles;
}

TEST(CardLod, TilesHalvePerLevelDownToOne) {
    EXPECT_EQ(tilesAtLevel(8, 3, 0), glm::uvec2(8, 3));
    EXPECT_EQ(tilesAtLevel(8, 3, 1), glm::uvec2(4, 2));
    EXPECT_EQ(tilesAtLevel(8, 3, 2), glm::uvec2(2, 1));
    EXPECT_EQ(tilesAtLevel(8, 3, 9), glm::uvec2(1, 1));
    EXPECT_EQ(lodLevel(1.0f, 0.0f, kMaxLevel), 0u);
    EXPECT_EQ(lodLevel(1.0f, 1.0f, kMaxLevel), 0u);
    EXPECT_EQ(lodLevel(0.5f, 1.0f, kMaxLevel), 1u);
    EXPECT_EQ(lodLevel(0.3f, 1.0f, kMaxLevel), 2u);
    EXPECT_EQ(lodLevel(1e-6f, 1.0f, kMaxLevel), kMaxLevel);
}

TEST(CardLod, PriorityFallsWithDistanceAndGrowsWithSize) {
    const scene::Bounds box{{0, 0, 0}, {1, 1, 1}};
    const scene::Bounds big{{0, 0, 0}, {2, 2, 2}};
    EXPECT_GT(cardPriority(box, {2, 0, 0}), cardPriority(box, {5, 0, 0}));
    EXPECT_GT(cardPriority(big, {5, 0, 0}), cardPriority(box, {5, 0, 0}));
    EXPECT_TRUE(std::isfinite(cardPriority(box, {0.5f, 0.5f, 0.5f}))); // inside
}

TEST(CardLod, EverythingAtFullDensityWhenItFits) {
    const std::vector<CardLodRequest> cards = row(10);
    const CardLodPlan plan = planCardLod(cards, priorities(cards, {}), 640, kMaxLevel);
    EXPECT_EQ(plan.reference, 0.0f);
    EXPECT_EQ(plan.tiles, 640u);
    for (uint8_t level : plan.levels) {
        EXPECT_EQ(level, 0u);
    }
}

TEST(CardLod, OverCapacityTheFarCardsGetCoarserAndThePlanIsTheFinestThatFits) {
    const std::vector<CardLodRequest> cards = row(10);
    const std::vector<float> p = priorities(cards, {});
    const uint64_t budget = 200; // of 640 at full density
    const CardLodPlan plan = planCardLod(cards, p, budget, kMaxLevel);
    EXPECT_LE(plan.tiles, budget);
    EXPECT_EQ(plan.tiles, tilesOf(cards, plan));
    EXPECT_EQ(plan.levels[0], 0u) << "the nearest card keeps its full density";
    for (size_t i = 1; i < cards.size(); ++i) {
        EXPECT_NE(plan.levels[i], kCardEvicted);
        EXPECT_GE(plan.levels[i], plan.levels[i - 1]) << "card " << i << " is farther";
    }
    EXPECT_GT(plan.levels.back(), 0u);
    // The finest plan: a slightly lower reference (finer cards) would not fit.
    uint64_t finer = 0;
    for (size_t i = 0; i < cards.size(); ++i) {
        const glm::uvec2 t = tilesAtLevel(8, 8, lodLevel(p[i], plan.reference * 0.99f, kMaxLevel));
        finer += uint64_t(t.x) * t.y;
    }
    EXPECT_GT(finer, budget);
}

TEST(CardLod, WhenEvenTheCoarsestDoesNotFitTheLeastUsefulAreEvicted) {
    const std::vector<CardLodRequest> cards = row(10);
    const CardLodPlan plan = planCardLod(cards, priorities(cards, {}), 6, kMaxLevel); // < 1 tile a card
    EXPECT_LE(plan.tiles, 6u);
    EXPECT_EQ(plan.tiles, tilesOf(cards, plan));
    // The evicted are the farthest: once a card is evicted, every farther one is too.
    uint32_t kept = 0;
    for (size_t i = 0; i < cards.size(); ++i) {
        if (plan.levels[i] != kCardEvicted) {
            ++kept;
            EXPECT_EQ(kept, i + 1) << "card " << i << " kept after a nearer one was evicted";
        }
    }
    EXPECT_GT(kept, 0u);
    EXPECT_LT(kept, cards.size());
}

TEST(CardLod, RejectsMismatchedPriorities) {
    const std::vector<CardLodRequest> cards = row(3);
    const std::vector<float> two = {1.0f, 1.0f};
    EXPECT_THROW(planCardLod(cards, two, 100, kMaxLevel), std::invalid_argument);
}

// A street of quads; the viewer walks from one end to the other.
scene::Scene street(uint32_t count) {
    scene::Scene s;
    s.name = "street";
    s.materials = {scene::Material{.name = "white"}};
    scene::MeshBuilder b("quad");
    b.quad({0, 0, 4}, {4, 0, 4}, {4, 0, 0}, {0, 0, 0}); // facing +y
    s.meshes.push_back(b.finish());
    for (uint32_t i = 0; i < count; ++i) {
        s.instances.push_back({.mesh = 0,
                               .transform = glm::translate(glm::mat4(1.0f), {10.0f * float(i), 0.0f, 0.0f}),
                               .name = "quad " + std::to_string(i)});
    }
    return s;
}

TEST(CardLod, UpdatesFollowTheViewerWithinTheBudgetAndHoldStillWhenItBarelyMoves) {
    const scene::Scene scene = street(16);
    SurfaceCacheSettings settings;
    settings.atlasSize = 16 * kTileSize;       // 256 tiles; the quads want 16 x 64 at full density
    settings.texelsPerUnit = 2.0f * kTileSize; // 4 units: 8 x 8 tiles
    settings.maxLodLevel = 4;
    settings.lodChangesPerFrame = 4;
    SurfaceCards cards(scene, settings, glm::vec3(0.0f, 1.0f, 2.0f));
    EXPECT_EQ(cards.level(0), 0u);
    EXPECT_GT(cards.level(15), 0u);
    const uint8_t farStart = cards.level(15);

    // Walk to the other end: the budget spreads the changes over frames.
    const glm::vec3 end(154.0f, 1.0f, 2.0f);
    uint32_t frames = 0;
    CardLodUpdate update;
    do {
        update = cards.updateLod(end);
        EXPECT_LE(update.changed(), settings.lodChangesPerFrame);
        ++frames;
    } while ((update.pending > 0 || update.changed() > 0) && frames < 100);
    EXPECT_GT(frames, 2u) << "the change was spread over frames";
    EXPECT_LT(frames, 100u);
    EXPECT_EQ(cards.level(15), 0u);
    EXPECT_GT(cards.level(0), 0u);
    EXPECT_LT(cards.level(15), farStart);
    EXPECT_LE(cards.atlas().usedTiles(), cards.atlas().tilesX() * cards.atlas().tilesY());
    // Reallocated cards are captured again.
    EXPECT_FALSE(cards.dirtyCards().empty());

    // A step of a hundredth of a unit changes nothing (hysteresis).
    const CardLodUpdate still = cards.updateLod(end + glm::vec3(0.01f, 0.0f, 0.0f));
    EXPECT_EQ(still.changed(), 0u);
    EXPECT_EQ(still.pending, 0u);
}

} // namespace
} // namespace lumina::surface_cache
