#include "gi/surface_cache/card_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {
namespace {

glm::vec3 boundsMin(const gpu::SurfaceCard& c) {
    return glm::vec3(c.boundsMinAndFlags);
}
glm::vec3 boundsMax(const gpu::SurfaceCard& c) {
    return glm::vec3(c.boundsMaxAndInstance);
}

struct Builder {
    std::span<const gpu::SurfaceCard> cards;
    CardBvh& out;

    // Fills node `node` with the subtree over out.cardOrder[first, first + count); returns its depth.
    uint32_t build(uint32_t node, uint32_t first, uint32_t count, uint32_t level) {
        if (level > LUMINA_CARD_BVH_STACK_SIZE) {
            throw std::logic_error("buildCardBvh: depth past the GPU stack of " +
                                   std::to_string(LUMINA_CARD_BVH_STACK_SIZE));
        }
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (uint32_t i = first; i < first + count; ++i) {
            lo = glm::min(lo, boundsMin(cards[out.cardOrder[i]]));
            hi = glm::max(hi, boundsMax(cards[out.cardOrder[i]]));
        }
        gpu::CardBvhNode& n = out.nodes[node];
        if (count <= LUMINA_CARD_BVH_LEAF_SIZE) {
            n.minAndLeftFirst = glm::vec4(lo, gpu::asfloat(first));
            n.maxAndCount = glm::vec4(hi, gpu::asfloat(count));
            n.cards = glm::uvec4(LUMINA_NO_CARD);
            for (uint32_t i = 0; i < count; ++i) {
                n.cards[int(i)] = out.cardOrder[first + i];
            }
            return 1;
        }
        const glm::vec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const uint32_t half = count / 2;
        auto begin = out.cardOrder.begin() + first;
        // Centroids doubled (min + max) to skip a multiply; ties broken by index so the tree does
        // not depend on the library's nth_element.
        std::nth_element(begin, begin + half, begin + count, [&](uint32_t a, uint32_t b) {
            const float ca = boundsMin(cards[a])[axis] + boundsMax(cards[a])[axis];
            const float cb = boundsMin(cards[b])[axis] + boundsMax(cards[b])[axis];
            return ca < cb || (ca == cb && a < b);
        });
        const uint32_t left = uint32_t(out.nodes.size());
        out.nodes.resize(out.nodes.size() + 2); // invalidates n
        gpu::CardBvhNode& interior = out.nodes[node];
        interior.minAndLeftFirst = glm::vec4(lo, gpu::asfloat(left));
        interior.maxAndCount = glm::vec4(hi, gpu::asfloat(0u));
        interior.cards = glm::uvec4(LUMINA_NO_CARD);
        const uint32_t leftDepth = build(left, first, half, level + 1);
        const uint32_t rightDepth = build(left + 1, first + half, count - half, level + 1);
        return 1 + std::max(leftDepth, rightDepth);
    }
};

void consider(const gpu::SurfaceCard& card, uint32_t index, const glm::vec3& p, const glm::vec3& n,
              uint32_t instance, const glm::vec3& seenFrom, CardOwner& best) {
    if (!gpu::cardContains(card, p) || !gpu::cardFacesRay(card, seenFrom)) {
        return;
    }
    const float score = gpu::cardOwnerScoreOnInstance(card, p, n, instance);
    if (score > best.score || (score == best.score && index < best.card)) {
        best = {index, score};
    }
}

} // namespace

CardBvh buildCardBvh(std::span<const gpu::SurfaceCard> cards) {
    CardBvh bvh;
    bvh.nodes.resize(1);
    if (cards.empty()) {
        // Bounds that hold nothing: the traversal rejects the root.
        bvh.nodes[0].minAndLeftFirst = glm::vec4(glm::vec3(std::numeric_limits<float>::max()), 0.0f);
        bvh.nodes[0].maxAndCount = glm::vec4(glm::vec3(-std::numeric_limits<float>::max()), 0.0f);
        bvh.nodes[0].cards = glm::uvec4(LUMINA_NO_CARD);
        bvh.depth = 1;
        return bvh;
    }
    for (size_t i = 0; i < cards.size(); ++i) {
        const glm::vec3 lo = boundsMin(cards[i]), hi = boundsMax(cards[i]);
        if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) ||
            !std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) {
            throw std::invalid_argument("buildCardBvh: card " + std::to_string(i) +
                                        " has empty or non-finite bounds");
        }
    }
    bvh.cardOrder.resize(cards.size());
    std::iota(bvh.cardOrder.begin(), bvh.cardOrder.end(), 0u);
    bvh.nodes.reserve(2 * cards.size() / LUMINA_CARD_BVH_LEAF_SIZE + 2);
    Builder builder{cards, bvh};
    bvh.depth = builder.build(0, 0, uint32_t(cards.size()), 1);
    return bvh;
}

CardOwner findCardOwner(const CardBvh& bvh, std::span<const gpu::SurfaceCard> cards, const glm::vec3& p,
                        const glm::vec3& n, uint32_t instance, const glm::vec3& seenFrom) {
    CardOwner best;
    std::vector<uint32_t> stack = {0u};
    while (!stack.empty()) {
        const gpu::CardBvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        if (!gpu::pointInBox(p, glm::vec3(node.minAndLeftFirst), glm::vec3(node.maxAndCount))) {
            continue;
        }
        const uint32_t count = nodeCardCount(node);
        if (count == 0) {
            stack.push_back(nodeLeftFirst(node) + 1);
            stack.push_back(nodeLeftFirst(node));
            continue;
        }
        for (uint32_t i = 0; i < count; ++i) {
            consider(cards[node.cards[int(i)]], node.cards[int(i)], p, n, instance, seenFrom, best);
        }
    }
    return best;
}

CardOwner findCardOwnerBruteForce(std::span<const gpu::SurfaceCard> cards, const glm::vec3& p,
                                  const glm::vec3& n, uint32_t instance, const glm::vec3& seenFrom) {
    CardOwner best;
    for (uint32_t i = 0; i < cards.size(); ++i) {
        consider(cards[i], i, p, n, instance, seenFrom, best);
    }
    return best;
}

} // namespace lumina::surface_cache
