#pragma once
// Cards of one mesh, in mesh space: the patches of its surface that the atlas stores, each
// seen orthographically along one of the six mesh axes.
//
// Every triangle goes to the axis direction its geometric normal (counter-clockwise winding)
// points along most (ties to the lower axis); a triangle of a double-sided material also goes
// to the opposite direction, for its back face. So a closed box gets the six cards of the
// design this follows (SimLumen: six per mesh), a one-sided quad gets one, and no card is
// spent on a direction with no surface facing it.
//
// More cards where a mesh needs them: within one direction, triangles are grouped into depth
// layers (a gap along the axis wider than layerGap x the mesh's extent separates layers), and
// front-to-back layers share a card only while their projections do not overlap. A shelf whose
// lower board hides under the upper one therefore gets a card per board, while the steps of a
// staircase share one. Past maxCardsPerAxis layers the deepest ones share a card.
#include "gi/bvh/bvh.h"
#include "gi/scene/scene.h"
#include "gi/surface_cache/surface_cache_settings.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lumina::surface_cache {

struct MeshCard {
    uint32_t axis = 0; // LUMINA_CARD_AXIS_* (surface_card_shared.h): the direction it looks from
    bvh::Aabb bounds;  // mesh space: the box of the card's triangles
    uint32_t triangleCount = 0;
    float projectedArea = 0; // the card's triangles projected onto its plane, summed
    bool twoSided = false;   // it holds back faces of a double-sided material
};

// The card frame of an axis direction, in mesh space: unit normal, and u, v with u x v = normal.
struct CardAxes {
    glm::vec3 normal;
    glm::vec3 u;
    glm::vec3 v;
};
CardAxes cardAxes(uint32_t axis);

// Throws std::invalid_argument naming the mesh for a mesh with no triangles, a zero-size mesh
// (all triangles degenerate) or non-finite positions.
std::vector<MeshCard> buildMeshCards(const scene::Mesh& mesh, std::span<const scene::Material> materials,
                                     const SurfaceCacheSettings& settings);

} // namespace lumina::surface_cache
