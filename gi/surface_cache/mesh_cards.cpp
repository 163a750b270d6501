#include "gi/surface_cache/mesh_cards.h"

#include "shaders/surface_cache/surface_card_shared.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {
namespace {

// One triangle as a card direction sees it.
struct Facing {
    float depthMin, depthMax; // along the direction's normal: larger is nearer the capture plane
    glm::vec2 uvMin, uvMax;   // its projection onto the card plane
    bvh::Aabb box;
    float projectedArea;
    bool backFace;
};

struct Layer {
    float depthMin, depthMax;
    std::vector<const Facing*> members;
    glm::vec2 uvMin{0.0f}, uvMax{0.0f};
};

bool rectsOverlap(const Layer& a, const Layer& b) {
    return a.uvMin.x < b.uvMax.x && b.uvMin.x < a.uvMax.x && a.uvMin.y < b.uvMax.y && b.uvMin.y < a.uvMax.y;
}

std::string meshLabel(const scene::Mesh& mesh) {
    return "mesh '" + mesh.name + "'";
}

// Which material each triangle uses is double-sided, from the submesh ranges.
std::vector<bool> doubleSidedTriangles(const scene::Mesh& mesh, std::span<const scene::Material> materials) {
    std::vector<bool> result(mesh.indices.size() / 3, false);
    for (const scene::Submesh& sub : mesh.submeshes) {
        const bool twoSided = sub.material < materials.size() && materials[sub.material].doubleSided;
        for (uint32_t i = sub.firstIndex / 3; i < (sub.firstIndex + sub.indexCount) / 3 && i < result.size();
             ++i) {
            result[i] = twoSided;
        }
    }
    return result;
}

// Groups a direction's triangles into depth layers, front to back, then lets neighbouring layers
// share a card while no two of its layers overlap in projection (nothing in it hides anything).
std::vector<std::vector<Layer>> groupLayers(std::vector<Facing>& facings, float gap, uint32_t maxCards) {
    std::sort(facings.begin(), facings.end(), [](const Facing& a, const Facing& b) {
        return a.depthMax > b.depthMax || (a.depthMax == b.depthMax && a.depthMin > b.depthMin);
    });
    std::vector<Layer> layers;
    for (const Facing& f : facings) {
        if (layers.empty() || f.depthMax < layers.back().depthMin - gap) {
            layers.push_back({f.depthMin, f.depthMax, {}, f.uvMin, f.uvMax});
        }
        Layer& layer = layers.back();
        layer.depthMin = std::min(layer.depthMin, f.depthMin);
        layer.uvMin = glm::min(layer.uvMin, f.uvMin);
        layer.uvMax = glm::max(layer.uvMax, f.uvMax);
        layer.members.push_back(&f);
    }
    std::vector<std::vector<Layer>> cards;
    for (Layer& layer : layers) {
        const bool fits =
            !cards.empty() && std::none_of(cards.back().begin(), cards.back().end(),
                                           [&](const Layer& other) { return rectsOverlap(layer, other); });
        if (!fits) {
            cards.emplace_back();
        }
        cards.back().push_back(std::move(layer));
    }
    while (cards.size() > maxCards) {
        std::vector<Layer> deepest = std::move(cards.back());
        cards.pop_back();
        cards.back().insert(cards.back().end(), deepest.begin(), deepest.end());
    }
    return cards;
}

} // namespace

CardAxes cardAxes(uint32_t axis) {
    if (axis > LUMINA_CARD_AXIS_NEG_Z) {
        throw std::invalid_argument("cardAxes: axis " + std::to_string(axis) + " is not 0..5");
    }
    const uint32_t a = axis / 2;
    const float sign = (axis % 2 == 0) ? 1.0f : -1.0f;
    CardAxes axes{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    axes.normal[a] = sign;
    axes.u[(a + 1) % 3] = sign; // flipped with the normal so that u x v = normal
    axes.v[(a + 2) % 3] = 1.0f;
    return axes;
}

std::vector<MeshCard> buildMeshCards(const scene::Mesh& mesh, std::span<const scene::Material> materials,
                                     const SurfaceCacheSettings& settings) {
    validate(settings);
    if (mesh.indices.size() < 3) {
        throw std::invalid_argument("buildMeshCards: " + meshLabel(mesh) + " has no triangles");
    }
    if (mesh.indices.size() % 3 != 0) {
        throw std::invalid_argument("buildMeshCards: " + meshLabel(mesh) + " has " +
                                    std::to_string(mesh.indices.size()) + " indices, not a multiple of 3");
    }
    bvh::Aabb meshBox;
    for (uint32_t index : mesh.indices) {
        if (index >= mesh.positions.size()) {
            throw std::invalid_argument("buildMeshCards: " + meshLabel(mesh) + " index " +
                                        std::to_string(index) + " past its " +
                                        std::to_string(mesh.positions.size()) + " positions");
        }
        const glm::vec3& p = mesh.positions[index];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw std::invalid_argument("buildMeshCards: " + meshLabel(mesh) + " vertex " +
                                        std::to_string(index) + " is not finite");
        }
        meshBox.extend(p);
    }
    const std::vector<bool> twoSided = doubleSidedTriangles(mesh, materials);

    std::array<std::vector<Facing>, 6> byAxis;
    for (size_t t = 0; t < mesh.indices.size() / 3; ++t) {
        const glm::vec3 v[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                                mesh.positions[mesh.indices[3 * t + 2]]};
        const glm::vec3 areaVector = 0.5f * glm::cross(v[1] - v[0], v[2] - v[0]);
        const glm::vec3 magnitude = glm::abs(areaVector);
        const float largest = std::max({magnitude.x, magnitude.y, magnitude.z});
        if (!(largest > 0.0f)) {
            continue; // degenerate: no normal, no area to store
        }
        const int a = magnitude.x == largest ? 0 : (magnitude.y == largest ? 1 : 2);
        const uint32_t front = 2u * uint32_t(a) + (areaVector[a] < 0.0f ? 1u : 0u);
        for (uint32_t side = 0; side < (twoSided[t] ? 2u : 1u); ++side) {
            const uint32_t axis = front ^ side; // the back face looks the other way
            const CardAxes axes = cardAxes(axis);
            Facing f{};
            f.depthMin = f.uvMin.x = f.uvMin.y = std::numeric_limits<float>::max();
            f.depthMax = f.uvMax.x = f.uvMax.y = -std::numeric_limits<float>::max();
            for (const glm::vec3& p : v) {
                const float depth = glm::dot(p, axes.normal);
                const glm::vec2 uv(glm::dot(p, axes.u), glm::dot(p, axes.v));
                f.depthMin = std::min(f.depthMin, depth);
                f.depthMax = std::max(f.depthMax, depth);
                f.uvMin = glm::min(f.uvMin, uv);
                f.uvMax = glm::max(f.uvMax, uv);
                f.box.extend(p);
            }
            f.projectedArea = magnitude[a];
            f.backFace = side == 1;
            byAxis[axis].push_back(f);
        }
    }

    std::vector<MeshCard> cards;
    for (uint32_t axis = 0; axis < 6; ++axis) {
        const float gap = settings.layerGap * meshBox.size()[axis / 2];
        for (const std::vector<Layer>& group : groupLayers(byAxis[axis], gap, settings.maxCardsPerAxis)) {
            MeshCard card;
            card.axis = axis;
            for (const Layer& layer : group) {
                for (const Facing* f : layer.members) {
                    card.bounds.extend(f->box);
                    card.projectedArea += f->projectedArea;
                    card.twoSided = card.twoSided || f->backFace;
                    ++card.triangleCount;
                }
            }
            cards.push_back(card);
        }
    }
    if (cards.empty()) {
        throw std::invalid_argument("buildMeshCards: " + meshLabel(mesh) +
                                    " has zero size: every triangle is degenerate");
    }
    return cards;
}

} // namespace lumina::surface_cache
