#include "gi/surface_cache/card_lod.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {
namespace {

// Halvings of the reference's search interval: far below a level's factor of two in precision.
constexpr int kReferenceSearchSteps = 48;

uint64_t tilesOf(const CardLodRequest& card, uint32_t level) {
    const glm::uvec2 tiles = tilesAtLevel(card.tilesX, card.tilesY, level);
    return uint64_t(tiles.x) * tiles.y;
}

// The level of a card under `reference`, or kCardEvicted past the coarsest.
uint8_t plannedLevel(float priority, float reference, uint32_t maxLevel) {
    const uint32_t level = lodLevel(priority, reference, maxLevel + 1);
    return level > maxLevel ? kCardEvicted : uint8_t(level);
}

// Tiles of the cards a reference keeps.
uint64_t planTiles(std::span<const CardLodRequest> cards, std::span<const float> priorities, float reference,
                   uint32_t maxLevel) {
    uint64_t tiles = 0;
    for (size_t i = 0; i < cards.size(); ++i) {
        const uint8_t level = plannedLevel(priorities[i], reference, maxLevel);
        if (level != kCardEvicted) {
            tiles += tilesOf(cards[i], level);
        }
    }
    return tiles;
}

} // namespace

float cardPriority(const scene::Bounds& bounds, const glm::vec3& viewer) {
    const float diagonal = glm::length(bounds.max - bounds.min);
    const glm::vec3 nearest = glm::clamp(viewer, bounds.min, bounds.max);
    const float distance = std::max(glm::length(viewer - nearest), 0.01f * diagonal);
    return distance > 0.0f ? diagonal / distance : 1.0f;
}

glm::uvec2 tilesAtLevel(uint32_t tilesX, uint32_t tilesY, uint32_t level) {
    const uint32_t shift = std::min(level, 31u);
    const auto halve = [&](uint32_t tiles) { return std::max(1u, (tiles + (1u << shift) - 1u) >> shift); };
    return {halve(tilesX), halve(tilesY)};
}

uint32_t lodLevel(float priority, float reference, uint32_t maxLevel) {
    if (!(reference > 0.0f) || priority >= reference) {
        return 0;
    }
    const float levels = std::ceil(std::log2(reference / std::max(priority, 1e-30f)));
    return uint32_t(std::clamp(levels, 0.0f, float(maxLevel)));
}

CardLodPlan planCardLod(std::span<const CardLodRequest> cards, std::span<const float> priorities,
                        uint64_t budgetTiles, uint32_t maxLevel) {
    if (priorities.size() != cards.size()) {
        throw std::invalid_argument("planCardLod: " + std::to_string(priorities.size()) + " priorities for " +
                                    std::to_string(cards.size()) + " cards");
    }
    CardLodPlan plan;
    plan.levels.assign(cards.size(), 0);
    plan.tiles = planTiles(cards, priorities, 0.0f, maxLevel);
    if (plan.tiles <= budgetTiles) {
        return plan; // everything at full density
    }
    // The smallest reference that fits, searched on a log scale: at lo every card is at level 0
    // (too many tiles), at hi every card is past the coarsest level, evicted (none). One
    // reference for all: a card twice as far as another is one level coarser, and the cards that
    // would be coarser than the coarsest level, the least useful, are the ones evicted.
    float lo = INFINITY, hi = -INFINITY;
    for (float p : priorities) {
        lo = std::min(lo, std::log2(std::max(p, 1e-30f)));
        hi = std::max(hi, std::log2(std::max(p, 1e-30f)) + float(maxLevel) + 1.0f);
    }
    for (int step = 0; step < kReferenceSearchSteps; ++step) {
        const float mid = 0.5f * (lo + hi);
        if (planTiles(cards, priorities, std::exp2(mid), maxLevel) <= budgetTiles) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    plan.reference = std::exp2(hi);
    plan.tiles = 0;
    for (size_t i = 0; i < cards.size(); ++i) {
        plan.levels[i] = plannedLevel(priorities[i], plan.reference, maxLevel);
        if (plan.levels[i] != kCardEvicted) {
            plan.tiles += tilesOf(cards[i], plan.levels[i]);
        }
    }
    return plan;
}

} // namespace lumina::surface_cache
