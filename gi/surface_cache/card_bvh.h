#pragma once
// The card BVH: finds the card that owns a world point (an SDF hit) in O(log n) instead of
// testing every card.
//
// Built top-down on the CPU over the cards' padded world bounds: split along the longest axis
// of the node's bounds at the median card centroid, until a node holds at most four cards
// (LUMINA_CARD_BVH_LEAF_SIZE). Flat array of 48-byte nodes (shaders/surface_cache/
// card_bvh_shared.h), children side by side. Median splits bound the depth by
// ceil(log2(n / 4)) + 1, far inside the GPU stack. Rebuilt whenever cards are added, removed or
// moved, in O(n log n) (nth_element per level).
//
// The owner of p for a unit normal n is the card, among those whose padded bounds hold p, with
// the highest cardOwnerScoreOnInstance (card_bvh_shared.h: normal agreement less distance outside
// the card's surface box, the cards of the instance an SDF hit names first), the lower index on
// equal scores, skipping cards that face away from the ray that found p; none when no card's
// bounds hold p.
// findCardOwner here and in card_bvh_traversal.hlsli apply that rule to the same floats.
#include "shaders/surface_cache/card_bvh_shared.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::surface_cache {

struct CardBvh {
    // Never empty: with no cards, one node whose bounds hold nothing.
    std::vector<gpu::CardBvhNode> nodes;
    std::vector<uint32_t> cardOrder; // card indices grouped by leaf (leaf leftFirst indexes this)
    uint32_t depth = 0;              // levels; 1 for a single leaf
};

CardBvh buildCardBvh(std::span<const gpu::SurfaceCard> cards);

struct CardOwner {
    uint32_t card = LUMINA_NO_CARD;
    float score = LUMINA_CARD_NO_SCORE;
};

// instance: the scene instance the point lies on, when known (an SDF hit), else LUMINA_ANY_INSTANCE.
// seenFrom: the direction of the ray that found p (the shaders' sdfSeenFrom); cards facing away
// from it are skipped (gpu::cardFacesRay). Zero: none skipped.
CardOwner findCardOwner(const CardBvh& bvh, std::span<const gpu::SurfaceCard> cards, const glm::vec3& p,
                        const glm::vec3& n, uint32_t instance = LUMINA_ANY_INSTANCE,
                        const glm::vec3& seenFrom = glm::vec3(0.0f));
// The same rule over every card, for tests.
CardOwner findCardOwnerBruteForce(std::span<const gpu::SurfaceCard> cards, const glm::vec3& p,
                                  const glm::vec3& n, uint32_t instance = LUMINA_ANY_INSTANCE,
                                  const glm::vec3& seenFrom = glm::vec3(0.0f));

// Node fields, decoded from the GPU layout.
inline uint32_t nodeCardCount(const gpu::CardBvhNode& node) {
    return gpu::asuint(node.maxAndCount.w);
}
inline uint32_t nodeLeftFirst(const gpu::CardBvhNode& node) {
    return gpu::asuint(node.minAndLeftFirst.w);
}

} // namespace lumina::surface_cache
