#pragma once
// The cards of a whole scene: each mesh's cards (mesh_cards.h) placed by each of its instances
// (card_placement.h), given atlas rectangles by the tile allocator and light masks.
//
// Cards are ordered instance by instance, each instance's in its mesh's card order, so an
// instance's cards are one range. Every card starts VISIBLE | DIRTY | STATIC; moving an instance
// makes its cards DYNAMIC and DIRTY. Capturing a card (the capture pass) clears DIRTY.
#include "gi/scene/scene.h"
#include "gi/surface_cache/card_placement.h"
#include "gi/surface_cache/mesh_cards.h"
#include "gi/surface_cache/surface_cache_settings.h"
#include "gi/surface_cache/tile_allocator.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lumina::surface_cache {

class SurfaceCards {
public:
    // Throws std::invalid_argument for bad settings, a zero-size mesh or too many lights, and
    // std::runtime_error when the atlas cannot hold the cards (naming the card and the space).
    explicit SurfaceCards(const scene::Scene& scene, const SurfaceCacheSettings& settings = {});

    const std::vector<gpu::SurfaceCard>& cards() const { return cards_; }
    std::span<const MeshCard> meshCards(uint32_t mesh) const { return meshCards_.at(mesh); }
    uint32_t firstCard(uint32_t instance) const { return instanceFirst_.at(instance); }
    uint32_t cardCount(uint32_t instance) const {
        return instanceFirst_.at(instance + 1) - instanceFirst_.at(instance);
    }
    // The instance a card belongs to.
    uint32_t instanceOf(uint32_t card) const;
    const TileAllocator& atlas() const { return atlas_; }
    const SurfaceCacheSettings& settings() const { return settings_; }

    // Places an instance's cards anew (they become DYNAMIC and DIRTY), with new atlas rectangles
    // where their size in tiles changed; a full atlas is defragmented first (the cards that move
    // become DIRTY). The card BVH must be rebuilt afterwards. Strong guarantee: when it throws
    // (atlas full, singular transform) nothing has changed.
    void moveInstance(uint32_t instance, const glm::mat4& transform, std::span<const scene::Light> lights);
    // The capture pass has written the card's texels at `frame`: clears DIRTY.
    void markCaptured(uint32_t card, uint32_t frame);
    std::vector<uint32_t> dirtyCards() const;

    // "card 3 (instance 'floor', mesh 'floor', +Y)", for error messages.
    std::string describe(uint32_t card) const;

private:
    void place(uint32_t card, const MeshCard& meshCard, const glm::mat4& transform,
               std::span<const scene::Light> lights, uint32_t flags);
    void allocate(uint32_t card, uint32_t tilesX, uint32_t tilesY);
    void setAtlasRect(uint32_t card, const TileRect& tiles);

    SurfaceCacheSettings settings_;
    TileAllocator atlas_;
    std::vector<std::vector<MeshCard>> meshCards_;
    std::vector<gpu::SurfaceCard> cards_;
    std::vector<TileRect> cardTiles_;
    std::vector<uint32_t> instanceFirst_; // instance count + 1 entries
    std::vector<std::string> instanceNames_;
    std::vector<std::string> meshNames_;
};

const char* axisName(uint32_t axis); // "+X" ... "-Z"

// A card's world bounds, padded as placed.
inline scene::Bounds cardBounds(const gpu::SurfaceCard& card) {
    return {glm::vec3(card.boundsMinAndFlags), glm::vec3(card.boundsMaxAndInstance)};
}

} // namespace lumina::surface_cache
