#include "gi/surface_cache/surface_cards.h"

#include "gi/surface_cache/light_mask.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace lumina::surface_cache {

const char* axisName(uint32_t axis) {
    static const char* const names[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return axis < 6 ? names[axis] : "?";
}

SurfaceCards::SurfaceCards(const scene::Scene& scene, const SurfaceCacheSettings& settings)
    : settings_((validate(settings), settings)),
      atlas_(settings.atlasSize / kTileSize, settings.atlasSize / kTileSize) {
    if (scene.lights.size() > LUMINA_CARD_LIGHT_MASK_BITS) {
        throw std::invalid_argument("SurfaceCards: scene '" + scene.name + "' has " +
                                    std::to_string(scene.lights.size()) + " lights; card light masks hold " +
                                    std::to_string(LUMINA_CARD_LIGHT_MASK_BITS));
    }
    for (const scene::Mesh& mesh : scene.meshes) {
        meshCards_.push_back(buildMeshCards(mesh, scene.materials, settings_));
        meshNames_.push_back(mesh.name);
    }
    instanceFirst_.push_back(0);
    for (const scene::Instance& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) {
            throw std::invalid_argument("SurfaceCards: instance '" + instance.name + "' names mesh " +
                                        std::to_string(instance.mesh) + " of " +
                                        std::to_string(scene.meshes.size()));
        }
        instanceFirst_.push_back(instanceFirst_.back() + uint32_t(meshCards_[instance.mesh].size()));
        instanceNames_.push_back(instance.name);
    }
    cards_.resize(instanceFirst_.back());
    cardTiles_.resize(cards_.size());
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        for (uint32_t c = 0; c < meshCards_[instance.mesh].size(); ++c) {
            const uint32_t card = instanceFirst_[i] + c;
            cards_[card].info = glm::uvec4(instance.mesh, c, meshCards_[instance.mesh][c].axis, 0u);
            cards_[card].boundsMaxAndInstance.w = gpu::asfloat(i);
            place(card, meshCards_[instance.mesh][c], instance.transform, scene.lights,
                  LUMINA_CARD_VISIBLE | LUMINA_CARD_DIRTY | LUMINA_CARD_STATIC);
        }
    }
}

uint32_t SurfaceCards::instanceOf(uint32_t card) const {
    if (card >= cards_.size()) {
        throw std::out_of_range("SurfaceCards: card " + std::to_string(card) + " of " +
                                std::to_string(cards_.size()));
    }
    return uint32_t(std::upper_bound(instanceFirst_.begin(), instanceFirst_.end(), card) -
                    instanceFirst_.begin()) -
           1u;
}

std::string SurfaceCards::describe(uint32_t card) const {
    const uint32_t instance = instanceOf(card);
    const gpu::SurfaceCard& c = cards_[card];
    return "card " + std::to_string(card) + " (instance '" + instanceNames_[instance] + "', mesh '" +
           meshNames_[c.info.x] + "', " + axisName(c.info.z) + ")";
}

void SurfaceCards::place(uint32_t card, const MeshCard& meshCard, const glm::mat4& transform,
                         std::span<const scene::Light> lights, uint32_t flags) {
    PlacedCard placed;
    try {
        placed = placeCard(meshCard, transform, settings_);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(describe(card) + ": " + e.what());
    }
    const glm::uvec4 info = cards_[card].info;
    const float instanceBits = cards_[card].boundsMaxAndInstance.w;
    gpu::SurfaceCard& c = cards_[card];
    c = placed.card;
    c.info = glm::uvec4(info.x, info.y, meshCard.axis, info.w);
    c.boundsMaxAndInstance.w = instanceBits;
    c.boundsMinAndFlags.w = gpu::asfloat(flags | (meshCard.twoSided ? LUMINA_CARD_TWO_SIDED : 0u));
    c.lightMask = lightMask(placed.unpaddedBounds, lights);
    const TileRect& old = cardTiles_[card];
    if (old.width != placed.tilesX || old.height != placed.tilesY) {
        if (old.area() != 0) {
            atlas_.release(old);
            cardTiles_[card] = {};
        }
        allocate(card, placed.tilesX, placed.tilesY);
    } else {
        setAtlasRect(card, old);
    }
}

void SurfaceCards::setAtlasRect(uint32_t card, const TileRect& tiles) {
    cardTiles_[card] = tiles;
    cards_[card].atlasRect = glm::uvec4(tiles.x * kTileSize, tiles.y * kTileSize, tiles.width * kTileSize,
                                        tiles.height * kTileSize);
}

void SurfaceCards::allocate(uint32_t card, uint32_t tilesX, uint32_t tilesY) {
    std::optional<TileRect> tiles = atlas_.tryAllocate(tilesX, tilesY, card);
    if (!tiles && atlas_.freeTiles() >= tilesX * tilesY) {
        // Enough space, but in pieces: repack the live cards (they must be captured again).
        for (const TileRelocation& moved : atlas_.defragment()) {
            setAtlasRect(moved.owner, moved.to);
            gpu::SurfaceCard& c = cards_[moved.owner];
            c.boundsMinAndFlags.w = gpu::asfloat(gpu::asuint(c.boundsMinAndFlags.w) | LUMINA_CARD_DIRTY);
        }
        tiles = atlas_.tryAllocate(tilesX, tilesY, card);
    }
    if (!tiles) {
        throw std::runtime_error(
            "surface cache atlas full: " + describe(card) + " needs " + std::to_string(tilesX) + "x" +
            std::to_string(tilesY) + " tiles; " + std::to_string(atlas_.freeTiles()) + " of " +
            std::to_string(atlas_.tilesX() * atlas_.tilesY()) + " tiles free, largest free block " +
            std::to_string(atlas_.largestFreeBlock()) + " tiles wide (atlasSize " +
            std::to_string(settings_.atlasSize) + ", texelsPerUnit " +
            std::to_string(settings_.texelsPerUnit) + ")");
    }
    setAtlasRect(card, *tiles);
}

void SurfaceCards::moveInstance(uint32_t instance, const glm::mat4& transform,
                                std::span<const scene::Light> lights) {
    if (instance + 1 >= instanceFirst_.size()) {
        throw std::out_of_range("SurfaceCards::moveInstance: instance " + std::to_string(instance) + " of " +
                                std::to_string(instanceFirst_.size() - 1));
    }
    // Placed on a copy and committed at the end: a move that does not fit (or a singular
    // transform) throws and leaves every card and the atlas as they were.
    SurfaceCards next = *this;
    const uint32_t first = instanceFirst_[instance], end = instanceFirst_[instance + 1];
    for (uint32_t card = first; card < end; ++card) {
        const gpu::SurfaceCard& c = next.cards_[card];
        const uint32_t keep = gpu::asuint(c.boundsMinAndFlags.w) & LUMINA_CARD_VISIBLE;
        next.place(card, meshCards_[c.info.x][c.info.y], transform, lights,
                   keep | LUMINA_CARD_DIRTY | LUMINA_CARD_DYNAMIC);
    }
    // The capture clears the texels another instance hides (card_capture_pass.h): the cards
    // the instance overlapped before or after the move are captured again.
    for (uint32_t card = 0; card < next.cards_.size(); ++card) {
        if (card >= first && card < end) {
            continue;
        }
        gpu::SurfaceCard& other = next.cards_[card];
        const scene::Bounds bounds = cardBounds(other);
        for (uint32_t moved = first; moved < end; ++moved) {
            if (bounds.overlaps(cardBounds(cards_[moved])) ||
                bounds.overlaps(cardBounds(next.cards_[moved]))) {
                other.boundsMinAndFlags.w =
                    gpu::asfloat(gpu::asuint(other.boundsMinAndFlags.w) | LUMINA_CARD_DIRTY);
                break;
            }
        }
    }
    *this = std::move(next);
}

void SurfaceCards::markCaptured(uint32_t card, uint32_t frame) {
    if (card >= cards_.size()) {
        throw std::out_of_range("SurfaceCards::markCaptured: card " + std::to_string(card) + " of " +
                                std::to_string(cards_.size()));
    }
    gpu::SurfaceCard& c = cards_[card];
    c.boundsMinAndFlags.w = gpu::asfloat(gpu::asuint(c.boundsMinAndFlags.w) & ~LUMINA_CARD_DIRTY);
    c.info.w = frame;
}

std::vector<uint32_t> SurfaceCards::dirtyCards() const {
    std::vector<uint32_t> dirty;
    for (uint32_t i = 0; i < cards_.size(); ++i) {
        if (gpu::asuint(cards_[i].boundsMinAndFlags.w) & LUMINA_CARD_DIRTY) {
            dirty.push_back(i);
        }
    }
    return dirty;
}

} // namespace lumina::surface_cache
