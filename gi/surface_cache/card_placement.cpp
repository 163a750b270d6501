#include "gi/surface_cache/card_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {
namespace {

// The range of dot(corner, axis) over the box's eight corners.
glm::vec2 projectBox(const bvh::Aabb& box, const glm::vec3& axis) {
    glm::vec2 range(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max());
    for (uint32_t c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1u) ? box.max.x : box.min.x, (c & 2u) ? box.max.y : box.min.y,
                               (c & 4u) ? box.max.z : box.min.z);
        const float d = glm::dot(corner, axis);
        range = glm::vec2(std::min(range.x, d), std::max(range.y, d));
    }
    return range;
}

bvh::Aabb transformBox(const bvh::Aabb& box, const glm::mat4& m) {
    bvh::Aabb out;
    for (uint32_t c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1u) ? box.max.x : box.min.x, (c & 2u) ? box.max.y : box.min.y,
                               (c & 4u) ? box.max.z : box.min.z);
        out.extend(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

// Tiles for `texels` texels along one side: at least one, at most the cap.
uint32_t tilesFor(float texels, uint32_t maxTiles) {
    const float tiles = std::ceil(texels / float(kTileSize));
    return uint32_t(std::clamp(tiles, 1.0f, float(maxTiles)));
}

} // namespace

PlacedCard placeCard(const MeshCard& meshCard, const glm::mat4& transform,
                     const SurfaceCacheSettings& settings) {
    const glm::mat3 linear(transform);
    const float det = glm::determinant(linear);
    if (!std::isfinite(det) || std::abs(det) < 1e-30f) {
        throw std::invalid_argument("placeCard: instance transform is singular or not finite (determinant " +
                                    std::to_string(det) + ")");
    }
    const CardAxes axes = cardAxes(meshCard.axis);
    const float scaleU = glm::length(linear * axes.u);
    const float scaleV = glm::length(linear * axes.v);
    const float scaleN = glm::length(linear * axes.normal);
    const float padding = paddingUnits(settings);

    // Mesh-space card frame. A flat card still gets a depth range: the padding, converted to
    // mesh units, on both sides, so that the map stays invertible and the capture has a slab.
    const glm::vec2 uRange = projectBox(meshCard.bounds, axes.u);
    const glm::vec2 vRange = projectBox(meshCard.bounds, axes.v);
    const glm::vec2 depth = projectBox(meshCard.bounds, axes.normal);
    const float uSize = std::max(uRange.y - uRange.x, padding / scaleU);
    const float vSize = std::max(vRange.y - vRange.x, padding / scaleV);
    const float front = depth.y + padding / scaleN;
    const float thickness = front - (depth.x - padding / scaleN);
    const glm::vec4 meshToCard0(axes.u / uSize, -uRange.x / uSize);
    const glm::vec4 meshToCard1(axes.v / vSize, -vRange.x / vSize);
    const glm::vec4 meshToCard2(-axes.normal / thickness, front / thickness);
    const glm::mat4 worldToMesh = glm::inverse(transform);

    PlacedCard placed;
    gpu::SurfaceCard& card = placed.card;
    card = {};
    // Row vector times matrix: (row . (worldToMesh . world)) = (row . worldToMesh) . world.
    card.worldToCard0 = meshToCard0 * worldToMesh;
    card.worldToCard1 = meshToCard1 * worldToMesh;
    card.worldToCard2 = meshToCard2 * worldToMesh;
    // Normals transform by the inverse transpose; mirrored instances keep the front on the side
    // their transformed normals point to (docs/conventions.md), so no sign flip.
    const glm::vec3 normal = glm::normalize(glm::transpose(glm::inverse(linear)) * axes.normal);

    placed.unpaddedBounds = transformBox(meshCard.bounds, transform);
    card.boundsMinAndFlags = glm::vec4(placed.unpaddedBounds.min - glm::vec3(padding), 0.0f);
    card.boundsMaxAndInstance = glm::vec4(placed.unpaddedBounds.max + glm::vec3(padding), 0.0f);
    card.normalAndPadding = glm::vec4(normal, padding);
    card.info = glm::uvec4(0u, 0u, meshCard.axis, 0u);
    placed.tilesX = tilesFor(uSize * scaleU * settings.texelsPerUnit, maxCardTilesIn(settings));
    placed.tilesY = tilesFor(vSize * scaleV * settings.texelsPerUnit, maxCardTilesIn(settings));
    return placed;
}

} // namespace lumina::surface_cache
