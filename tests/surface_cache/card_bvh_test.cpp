// The card BVH (card_bvh.h) against brute force on the CPU, its structure, and the owner rule.
#include "gi/surface_cache/card_bvh.h"
#include "tests/surface_cache/random_cards.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace lumina::surface_cache {
namespace {

gpu::SurfaceCard flatCard(glm::vec3 lo, glm::vec3 hi, glm::vec3 normal, float padding,
                          uint32_t instance = 0) {
    gpu::SurfaceCard card{};
    card.boundsMinAndFlags = glm::vec4(lo - glm::vec3(padding), 0.0f);
    card.boundsMaxAndInstance = glm::vec4(hi + glm::vec3(padding), gpu::asfloat(instance));
    card.normalAndPadding = glm::vec4(normal, padding);
    return card;
}

TEST(SurfaceCacheCardBvh, NodesHoldTheirCardsAndEveryCardIsInOneLeaf) {
    for (uint32_t count : {1u, 4u, 5u, 17u, 100u, 1000u, 4099u}) {
        SCOPED_TRACE(count);
        const std::vector<gpu::SurfaceCard> cards = test::randomCards(count, count);
        const CardBvh bvh = buildCardBvh(cards);
        std::vector<uint32_t> seen(count, 0);
        uint32_t leaves = 0;
        for (const gpu::CardBvhNode& node : bvh.nodes) {
            const glm::vec3 lo(node.minAndLeftFirst), hi(node.maxAndCount);
            const uint32_t n = nodeCardCount(node);
            const auto holds = [&](glm::vec3 a, glm::vec3 b) {
                return glm::all(glm::lessThanEqual(lo, a)) && glm::all(glm::greaterThanEqual(hi, b));
            };
            if (n == 0) {
                const uint32_t left = nodeLeftFirst(node);
                ASSERT_LT(left + 1, bvh.nodes.size());
                for (uint32_t child = left; child < left + 2; ++child) {
                    EXPECT_TRUE(holds(glm::vec3(bvh.nodes[child].minAndLeftFirst),
                                      glm::vec3(bvh.nodes[child].maxAndCount)));
                }
                continue;
            }
            ++leaves;
            ASSERT_LE(n, LUMINA_CARD_BVH_LEAF_SIZE);
            for (uint32_t i = 0; i < 4; ++i) {
                const uint32_t card = node.cards[int(i)];
                if (i >= n) {
                    EXPECT_EQ(card, LUMINA_NO_CARD);
                    continue;
                }
                EXPECT_EQ(card, bvh.cardOrder[nodeLeftFirst(node) + i]);
                ++seen[card];
                EXPECT_TRUE(holds(glm::vec3(cards[card].boundsMinAndFlags),
                                  glm::vec3(cards[card].boundsMaxAndInstance)));
            }
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](uint32_t s) { return s == 1; }));
        EXPECT_EQ(bvh.nodes.size(), 2 * leaves - 1);
        // Median splits: depth at most ceil(log2(n / 4)) + 1.
        const uint32_t bound = count <= 4 ? 1u : uint32_t(std::ceil(std::log2(count / 4.0))) + 1u;
        EXPECT_LE(bvh.depth, bound);
    }
}

TEST(SurfaceCacheCardBvh, OwnerMatchesBruteForce) {
    for (uint32_t count : {0u, 1u, 3u, 50u, 2000u}) {
        SCOPED_TRACE(count);
        const std::vector<gpu::SurfaceCard> cards = test::randomCards(count, 100 + count);
        const CardBvh bvh = buildCardBvh(cards);
        uint32_t found = 0;
        for (const test::OwnerQuery& q : test::randomQueries(cards, 20000, count)) {
            const CardOwner fast = findCardOwner(bvh, cards, q.position, q.normal, q.instance, q.seenFrom);
            const CardOwner slow =
                findCardOwnerBruteForce(cards, q.position, q.normal, q.instance, q.seenFrom);
            ASSERT_EQ(fast.card, slow.card);
            ASSERT_EQ(fast.score, slow.score);
            found += fast.card != LUMINA_NO_CARD;
        }
        if (count >= 50) {
            EXPECT_GT(found, 8000u); // most queries were near cards: the test exercised owners
        }
    }
}

TEST(SurfaceCacheCardBvh, OwnerIsTheCardFacingTheNormalAndThroughThePoint) {
    const float pad = 1.0f;
    const std::vector<gpu::SurfaceCard> cards = {
        flatCard({0, 0, 0}, {100, 0, 100}, {0, 1, 0}, pad),          // 0: floor
        flatCard({0, 0, 0}, {0, 100, 100}, {1, 0, 0}, pad),          // 1: wall
        flatCard({0, 100, 0}, {100, 100, 100}, {0, -1, 0}, pad),     // 2: ceiling
        flatCard({40, 99.8f, 40}, {60, 99.8f, 60}, {0, -1, 0}, pad), // 3: a light just under it
    };
    const CardBvh bvh = buildCardBvh(cards);
    const auto owner = [&](glm::vec3 p, glm::vec3 n) { return findCardOwner(bvh, cards, p, n).card; };
    EXPECT_EQ(owner({50, 0, 50}, {0, 1, 0}), 0u);
    EXPECT_EQ(owner({0.1f, 0.1f, 50}, {0, 1, 0}), 0u);            // the corner: the floor faces the normal
    EXPECT_EQ(owner({0.1f, 0.1f, 50}, {1, 0, 0}), 1u);            // ... the wall faces this one
    EXPECT_EQ(owner({50, 99.8f, 50}, {0, -1, 0}), 3u);            // on the light, not the ceiling
    EXPECT_EQ(owner({50, 100.0f, 50}, {0, -1, 0}), 2u);           // on the ceiling above it
    EXPECT_EQ(owner({50, 50, 50}, {0, 1, 0}), LUMINA_NO_CARD);    // mid-air
    EXPECT_EQ(owner({50, -1.5f, 50}, {0, 1, 0}), LUMINA_NO_CARD); // beyond the padding
    // Equal scores: the lower index.
    const std::vector<gpu::SurfaceCard> twins = {cards[0], cards[0]};
    EXPECT_EQ(findCardOwner(buildCardBvh(twins), twins, {1, 0, 1}, {0, 1, 0}).card, 0u);
}

// Where two zero-thickness walls meet, a hit within a voxel of one wall's edge has an SDF gradient
// along that wall: its two cards (one a side) then score about alike, and the sealed box's probes
// read the sky-lit outside (docs/gi.md, energy 41.). The ray that found the hit can only see the side
// that faces it.
TEST(SurfaceCacheCardBvh, ARayReadsTheSideOfAnOpenSurfaceThatFacesIt) {
    const float pad = 1.0f;
    const std::vector<gpu::SurfaceCard> cards = {
        flatCard({100, 0, 0}, {100, 100, 100}, {1, 0, 0}, pad),  // 0: the wall's outside
        flatCard({100, 0, 0}, {100, 100, 100}, {-1, 0, 0}, pad), // 1: its inside
    };
    const CardBvh bvh = buildCardBvh(cards);
    // The gradient near the edge z = 0, turned to face a ray going +x and -z: mostly +z, and a
    // little +x, so the outside scores higher.
    const glm::vec3 p(100, 60, 3), n = glm::normalize(glm::vec3(0.25f, 0, 0.968f));
    const glm::vec3 ray = glm::normalize(glm::vec3(0.943f, -0.075f, -0.325f));
    EXPECT_EQ(findCardOwner(bvh, cards, p, n).card, 0u);                           // no ray given
    EXPECT_EQ(findCardOwner(bvh, cards, p, n, LUMINA_ANY_INSTANCE, ray).card, 1u); // the inside
    EXPECT_EQ(findCardOwnerBruteForce(cards, p, n, LUMINA_ANY_INSTANCE, ray).card, 1u);
    EXPECT_EQ(findCardOwner(bvh, cards, p, -n, LUMINA_ANY_INSTANCE, -ray).card, 0u); // from outside
    // A ray along the wall's plane sees both sides: the score decides.
    EXPECT_EQ(findCardOwner(bvh, cards, p, n, LUMINA_ANY_INSTANCE, glm::vec3(0, 0, -1)).card, 0u);
}

// two_rooms' panel fills a hole in the ceiling, in its plane and facing the same way: only the
// instance an SDF hit names tells the two cards apart (docs/gi.md, 33.).
TEST(SurfaceCacheCardBvh, AHitOnAnInstanceReadsItsOwnCards) {
    const float pad = 1.0f;
    const uint32_t shell = 0, panel = 2;
    const std::vector<gpu::SurfaceCard> cards = {
        flatCard({0, 100, 0}, {100, 100, 100}, {0, -1, 0}, pad, shell), // 0: the ceiling, holed
        flatCard({40, 100, 40}, {60, 100, 60}, {0, -1, 0}, pad, panel), // 1: the panel in its hole
        flatCard({0, 0, 0}, {100, 0, 100}, {0, 1, 0}, pad, shell),      // 2: the floor
    };
    const CardBvh bvh = buildCardBvh(cards);
    const auto owner = [&](glm::vec3 p, glm::vec3 n, uint32_t instance) {
        return findCardOwner(bvh, cards, p, n, instance).card;
    };
    EXPECT_EQ(owner({50, 100, 50}, {0, -1, 0}, LUMINA_ANY_INSTANCE), 0u); // equal scores: the lower index
    EXPECT_EQ(owner({50, 100, 50}, {0, -1, 0}, panel), 1u);
    EXPECT_EQ(owner({50, 100, 50}, {0, -1, 0}, shell), 0u);
    // The hit instance's card wins even where another fits the normal better...
    EXPECT_EQ(owner({50, 100, 50}, {0, 1, 0}, panel), 1u);
    // ... but where none of its cards holds the point, the others still own it.
    EXPECT_EQ(owner({20, 100, 20}, {0, -1, 0}, panel), 0u);
    EXPECT_EQ(owner({50, 0, 50}, {0, 1, 0}, panel), 2u);
    EXPECT_EQ(owner({50, 50, 50}, {0, 1, 0}, panel), LUMINA_NO_CARD);
    EXPECT_EQ(findCardOwnerBruteForce(cards, {50, 100, 50}, {0, -1, 0}, panel).card, 1u);
}

TEST(SurfaceCacheCardBvh, BadCardsThrow) {
    std::vector<gpu::SurfaceCard> cards = test::randomCards(3, 1);
    cards[1].boundsMinAndFlags.x = cards[1].boundsMaxAndInstance.x + 1.0f;
    EXPECT_THROW(buildCardBvh(cards), std::invalid_argument);
    cards[1].boundsMinAndFlags.x = std::nanf("");
    EXPECT_THROW(buildCardBvh(cards), std::invalid_argument);
}

} // namespace
} // namespace lumina::surface_cache
