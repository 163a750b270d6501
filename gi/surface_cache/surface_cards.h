#pragma once
// The cards of a whole scene: each mesh's cards (mesh_cards.h) placed by each of its instances
// (card_placement.h), given atlas rectangles by the tile allocator at a level of detail
// (card_lod.h), and light masks.
//
// Cards are ordered instance by instance, each instance's in its mesh's card order, so an
// instance's cards are one range. Every card starts DIRTY | STATIC, and VISIBLE while it holds
// atlas texels; moving an instance makes its cards DYNAMIC and DIRTY. Capturing a card (the
// capture pass) clears DIRTY.
//
// The atlas never overflows: when the cards do not fit at full density, each card's level
// follows its projected size from the viewer, and the least useful cards are evicted (they keep
// no texels; hits on them read the voxel lighting). updateLod() follows a moving viewer within
// a budget of reallocations per frame.
#include "gi/scene/scene.h"
#include "gi/surface_cache/card_lod.h"
#include "gi/surface_cache/card_placement.h"
#include "gi/surface_cache/mesh_cards.h"
#include "gi/surface_cache/surface_cache_settings.h"
#include "gi/surface_cache/tile_allocator.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lumina::surface_cache {

// What one updateLod() changed.
struct CardLodUpdate {
    uint32_t refined = 0;   // cards given a finer level
    uint32_t coarsened = 0; // cards given a coarser level
    uint32_t evicted = 0;   // cards that lost their texels
    uint32_t restored = 0;  // evicted cards given texels again
    uint32_t pending = 0;   // changes left for later frames (budget, or no space yet)
    uint32_t changed() const { return refined + coarsened + evicted + restored; }
};

// How full the atlas is and at what levels the cards are.
struct AtlasOccupancy {
    uint32_t usedTiles = 0;
    uint32_t totalTiles = 0;
    std::vector<uint32_t> cardsAtLevel; // index: level 0 .. maxLodLevel
    uint32_t evicted = 0;
    uint32_t cards = 0;
};

class SurfaceCards {
public:
    // Cards placed with levels for a viewer at `viewer` (the scene camera's position when none).
    // Throws std::invalid_argument for bad settings, a zero-size mesh, a singular transform or
    // too many lights; never for a full atlas.
    explicit SurfaceCards(const scene::Scene& scene, const SurfaceCacheSettings& settings = {},
                          std::optional<glm::vec3> viewer = std::nullopt);

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

    // A card's level (0: full density), or kCardEvicted.
    uint8_t level(uint32_t card) const { return levels_.at(card); }
    // A card's size in tiles at full density.
    glm::uvec2 fullTiles(uint32_t card) const { return fullTiles_.at(card); }
    // A card's projected size from the viewer of the last plan (card_lod.h).
    float priority(uint32_t card) const { return priorities_.at(card); }
    AtlasOccupancy occupancy() const;

    // Re-plans the levels for a viewer at `viewer` and reallocates at most
    // settings().lodChangesPerFrame cards (coarser and evicted ones first, to make room, then
    // the most useful finer ones); changed cards become DIRTY. The card BVH needs no rebuild
    // (bounds do not change), the card buffer and tile lists need an upload when changed() > 0.
    CardLodUpdate updateLod(const glm::vec3& viewer);

    // Places an instance's cards anew (they become DYNAMIC and DIRTY), with new atlas rectangles
    // where their size in tiles changed (a coarser level, or eviction, where the space is not
    // there). The card BVH must be rebuilt afterwards. Throws std::invalid_argument for a
    // singular transform, with nothing changed.
    void moveInstance(uint32_t instance, const glm::mat4& transform, std::span<const scene::Light> lights);
    // Recomputes every card's light mask for `lights` (the scene's lights now). Returns the cards
    // that a light in `changedLights` reached before or reaches now: their direct light must be
    // computed again. Throws std::invalid_argument for more lights than mask bits.
    std::vector<uint32_t> setLights(std::span<const scene::Light> lights,
                                    std::span<const uint32_t> changedLights);
    // The instance's cards are captured again (its material changed: emission, albedo).
    void markInstanceDirty(uint32_t instance);
    // The capture pass has written the card's texels at `frame`: clears DIRTY.
    void markCaptured(uint32_t card, uint32_t frame);
    // Dirty cards that hold texels, most useful first; at most `limit`.
    std::vector<uint32_t> dirtyCards(uint32_t limit = UINT32_MAX) const;
    // How many dirtyCards() would return without a limit.
    uint32_t dirtyCardCount() const;

    // "card 3 (instance 'floor', mesh 'floor', +Y)", for error messages.
    std::string describe(uint32_t card) const;

private:
    // Sets the card's world placement and light mask; keeps its atlas rectangle.
    void placeGeometry(uint32_t card, const MeshCard& meshCard, const glm::mat4& transform,
                       std::span<const scene::Light> lights, uint32_t flags);
    // Gives the card a rectangle at `level` or, failing that, the next coarser level that fits
    // (defragmenting once when the free tiles would hold it), else evicts it. Returns the level
    // it got. The old rectangle is released first unless `keepOnFailure` (then a card that gets
    // nothing at `level` keeps what it had, and the result is its old level).
    uint8_t assign(uint32_t card, uint32_t level, bool keepOnFailure);
    void evict(uint32_t card);
    void setAtlasRect(uint32_t card, const TileRect& tiles);
    void setFlag(uint32_t card, uint32_t flag, bool on);
    std::vector<float> prioritiesFrom(const glm::vec3& viewer) const;
    CardLodPlan plan(const std::vector<float>& priorities) const;

    SurfaceCacheSettings settings_;
    TileAllocator atlas_;
    std::vector<std::vector<MeshCard>> meshCards_;
    std::vector<gpu::SurfaceCard> cards_;
    std::vector<TileRect> cardTiles_;      // zero area while evicted
    std::vector<glm::uvec2> fullTiles_;    // tiles at level 0
    std::vector<uint8_t> levels_;          // current level, or kCardEvicted
    std::vector<float> priorities_;        // from the last plan's viewer
    std::vector<bvh::Aabb> surfaceBounds_; // per card: its surface's world box (unpadded), for masks
    std::vector<uint32_t> instanceFirst_;  // instance count + 1 entries
    std::vector<std::string> instanceNames_;
    std::vector<std::string> meshNames_;
};

// "4107 of 16384 tiles (25.1%); 1210 cards: 800 at full density, 300 at 1/2, 100 at 1/4; 10
// evicted (lit by the voxel lighting)"
std::string toString(const AtlasOccupancy& occupancy);

const char* axisName(uint32_t axis); // "+X" ... "-Z"

// A card's world bounds, padded as placed.
inline scene::Bounds cardBounds(const gpu::SurfaceCard& card) {
    return {glm::vec3(card.boundsMinAndFlags), glm::vec3(card.boundsMaxAndInstance)};
}

} // namespace lumina::surface_cache
