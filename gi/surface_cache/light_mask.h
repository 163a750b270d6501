#pragma once
// Which scene lights can reach a card: the 128-bit mask of SurfaceCard::lightMask, so that the
// direct-light update re-shades only the cards a changed light touches.
//
// Conservative: a bit may be set for a light that ends up lighting nothing (occluded, or facing
// away), never cleared for one that lights the card. Directional lights and point or spot lights
// of unlimited range reach everything; a ranged light reaches a box its range sphere touches, and
// a spot light only a box whose bounding sphere its outer cone touches.
#include "gi/bvh/bvh.h"
#include "gi/scene/scene.h"

#include <glm/glm.hpp>
#include <span>

namespace lumina::surface_cache {

// Throws std::invalid_argument when there are more lights than mask bits (128).
glm::uvec4 lightMask(const bvh::Aabb& worldBounds, std::span<const scene::Light> lights);

bool lightReaches(const scene::Light& light, const bvh::Aabb& worldBounds);

} // namespace lumina::surface_cache
