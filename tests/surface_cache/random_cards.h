#pragma once
// Random cards and owner queries for the card BVH tests (CPU and GPU): boxes of mixed sizes,
// some flat like real cards, with axis normals and a few tilted ones, on kRandomInstances
// instances; queries mostly on or near card bounds (where ownership is decided), some anywhere,
// half of them naming an instance (as an SDF hit does), now and then one without cards.
#include "shaders/surface_cache/card_bvh_shared.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <glm/glm.hpp>
#include <random>
#include <vector>

namespace lumina::surface_cache::test {

inline constexpr uint32_t kRandomInstances = 6;

inline std::vector<gpu::SurfaceCard> randomCards(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(-50.0f, 50.0f), size(0.0f, 8.0f), unit(-1.0f, 1.0f);
    std::vector<gpu::SurfaceCard> cards(count);
    for (uint32_t i = 0; i < count; ++i) {
        const float padding = 0.05f + 0.2f * (unit(rng) + 1.0f);
        glm::vec3 extent(size(rng), size(rng), size(rng));
        const int flatAxis = int(rng() % 4);
        if (flatAxis < 3) {
            extent[flatAxis] = 0.0f; // a flat card, like a wall's
        }
        const glm::vec3 lo(position(rng), position(rng), position(rng));
        glm::vec3 normal(0.0f);
        normal[int(rng() % 3)] = (rng() % 2) ? 1.0f : -1.0f;
        if (rng() % 5 == 0) {
            normal = glm::normalize(normal + 0.5f * glm::vec3(unit(rng), unit(rng), unit(rng)));
        }
        gpu::SurfaceCard& card = cards[i];
        card = {};
        card.boundsMinAndFlags = glm::vec4(lo - glm::vec3(padding), 0.0f);
        card.boundsMaxAndInstance =
            glm::vec4(lo + extent + glm::vec3(padding), gpu::asfloat(rng() % kRandomInstances));
        card.normalAndPadding = glm::vec4(normal, padding);
    }
    return cards;
}

struct OwnerQuery {
    glm::vec3 position;
    glm::vec3 normal;
    uint32_t instance = LUMINA_ANY_INSTANCE;
    glm::vec3 seenFrom{0.0f}; // the ray that found the point; zero: no ray
};

inline std::vector<OwnerQuery> randomQueries(const std::vector<gpu::SurfaceCard>& cards, uint32_t count,
                                             uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), anywhere(-60.0f, 60.0f);
    std::vector<OwnerQuery> queries(count);
    for (uint32_t i = 0; i < count; ++i) {
        glm::vec3 n(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
        queries[i].normal = glm::length(n) > 1e-3f ? glm::normalize(n) : glm::vec3(0, 1, 0);
        if (i % 2 == 1) {
            queries[i].instance = rng() % (kRandomInstances + 1);
        }
        if (i % 3 == 2) {
            // A third of the queries come with a ray's direction, about as often against the
            // normal as along it: its back-facing candidates are skipped.
            const glm::vec3 d(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
            queries[i].seenFrom = glm::length(d) > 1e-3f ? glm::normalize(d) : glm::vec3(0.0f);
        }
        if (i % 4 == 0 || cards.empty()) {
            queries[i].position = glm::vec3(anywhere(rng), anywhere(rng), anywhere(rng));
            continue;
        }
        // A point in (or just around) a card's padded bounds.
        const gpu::SurfaceCard& card = cards[rng() % cards.size()];
        const glm::vec3 lo(card.boundsMinAndFlags), hi(card.boundsMaxAndInstance);
        const glm::vec3 t(unit(rng) * 1.2f - 0.1f, unit(rng) * 1.2f - 0.1f, unit(rng) * 1.2f - 0.1f);
        queries[i].position = lo + t * (hi - lo);
        if (i % 8 == 1) {
            queries[i].position = lo; // exactly on a corner: containment ties
        }
    }
    return queries;
}

} // namespace lumina::surface_cache::test
