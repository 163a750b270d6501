#pragma once
// How finely each card is kept in the atlas: a level per card (the LOD of Lumen's card pages).
// Level 0 is the card's full density (SurfaceCacheSettings::texelsPerUnit); level L halves its
// sides L times, down to one tile. The atlas is a fixed pool, so the plan never fails:
//
//   1. every card fits at level 0: all level 0 (small scenes never lose texels);
//   2. otherwise levels follow each card's usefulness from the viewer, its projected size
//      p = world diagonal / distance: level = ceil(log2(reference / p)), 0 when p >= reference,
//      with the smallest reference (the finest plan) whose tiles fit the atlas;
//   3. cards whose level would be past the coarsest (the least useful: far, small) are evicted:
//      they keep no texels, and SDF hits on them read the voxel lighting instead. Evicting a far
//      card costs less than coarsening every near one.
//
// The allocator (SurfaceCards) then hands out rectangles most useful first and falls back to a
// coarser level, then to eviction, where the buddy allocator's fragmentation leaves no block.
#include "gi/scene/scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::surface_cache {

inline constexpr uint8_t kCardEvicted = 0xFF; // a plan's level for a card that keeps no texels

// A card's size in tiles at level 0 and its padded world bounds.
struct CardLodRequest {
    uint32_t tilesX = 1;
    uint32_t tilesY = 1;
    scene::Bounds bounds;
};

struct CardLodPlan {
    std::vector<uint8_t> levels; // per card: its level, or kCardEvicted
    float reference = 0.0f;      // projected size at and above which a card is at level 0
    uint64_t tiles = 0;          // tiles the plan's cards take
};

// The card's usefulness from `viewer`: its world diagonal over the distance from the viewer to its
// box (the size it projects to, in radians for small angles). A viewer inside the box sees it at
// a hundredth of its diagonal, the closest any card can be.
float cardPriority(const scene::Bounds& bounds, const glm::vec3& viewer);

// The card's size in tiles at `level`: each side halved `level` times, rounded up, at least 1.
glm::uvec2 tilesAtLevel(uint32_t tilesX, uint32_t tilesY, uint32_t level);

// The level a card of projected size `priority` gets under `reference` (0 when reference is 0).
uint32_t lodLevel(float priority, float reference, uint32_t maxLevel);

// Levels for every card such that their tiles fit `budgetTiles` (see above). `priorities[i]` is
// cards[i]'s cardPriority. Deterministic: ties break by card index.
CardLodPlan planCardLod(std::span<const CardLodRequest> cards, std::span<const float> priorities,
                        uint64_t budgetTiles, uint32_t maxLevel);

} // namespace lumina::surface_cache
