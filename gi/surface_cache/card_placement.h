#pragma once
// A mesh card placed in the world by an instance transform: the GPU card (world-to-card map,
// world bounds, normal, flags) and the tiles it needs, everything but its atlas position and
// light mask, which gi/surface_cache/surface_cards.h fills in.
//
// Cards live per mesh in mesh space (mesh_cards.h) and are placed per instance: every instance
// needs its own texels anyway (its lighting differs), and an instance that moves re-places its
// cards without touching its mesh's.
#include "gi/surface_cache/mesh_cards.h"
#include "gi/surface_cache/tile_allocator.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <glm/glm.hpp>

namespace lumina::surface_cache {

struct PlacedCard {
    gpu::SurfaceCard card;    // atlasRect, lightMask and info.w are zero
    uint32_t tilesX = 0;      // atlas tiles it needs across (u)
    uint32_t tilesY = 0;      // and down (v)
    bvh::Aabb unpaddedBounds; // world box of the card's surface
};

// Throws std::invalid_argument for a transform that is singular or not finite.
PlacedCard placeCard(const MeshCard& meshCard, const glm::mat4& transform,
                     const SurfaceCacheSettings& settings);

} // namespace lumina::surface_cache
