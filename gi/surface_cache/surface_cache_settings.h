#pragma once
// What a scene's surface cache is built with: atlas size, card resolution and card generation.
// Lengths are in scene units (gi/scene/units.h), so texelsPerUnit depends on the scene's scale:
// 1 texel per unit is 1 mm texels in the Cornell box (millimetres).
#include "gi/surface_cache/tile_allocator.h"

#include <cstdint>

namespace lumina::surface_cache {

struct SurfaceCacheSettings {
    uint32_t atlasSize = 4096;     // texels per side of every atlas layer; a multiple of 64
    float texelsPerUnit = 1.0f;    // card texel density before rounding up to whole tiles
    uint32_t maxCardTexels = 1024; // a card side never exceeds this many texels (rounded down to
                                   // whole tiles, at least one; never more than the atlas side):
                                   // large surfaces get a lower density instead of filling the atlas
    float paddingTexels = 2.0f;    // card bounds grow by this many texels (1/texelsPerUnit each)...
    float minPaddingUnits = 0.0f;  // ...or by this much in scene units, whichever is larger: SDF hits
                                   // lie off the surface by up to about half a mesh-SDF voxel (open
                                   // surfaces, docs/sdf.md), so a renderer sets this to that voxel size
                                   // for the hits to find their cards
    uint32_t maxCardsPerAxis = 4;  // depth layers per mesh axis direction before the deepest merge
    float layerGap = 0.1f;         // a gap along the axis wider than this fraction of the mesh's extent
                                   // starts a new depth layer (see mesh_cards.h)

    // Level of detail (card_lod.h): when the cards do not fit at full density, each gets a level
    // from its projected size, and the least useful are evicted.
    uint32_t maxLodLevel = 6;         // the coarsest level halves a card's sides this many times
    float atlasFill = 0.9f;           // plans fill at most this fraction of the atlas's tiles: the
                                      // buddy allocator needs slack to place what the plan counts
    float lodHysteresis = 1.5f;       // a card changes level only when its projected size moved
                                      // past the level's bound by this factor (no flicker at a bound)
    uint32_t lodChangesPerFrame = 64; // cards given a new level (reallocated) per frame at most
    uint32_t capturesPerFrame = 50;   // cards captured per update after the first (which captures
                                      // all): a large change is spread over frames, never a spike
};

// Throws std::invalid_argument naming the first setting out of range.
void validate(const SurfaceCacheSettings& settings);

// The padding of card bounds in scene units.
inline float paddingUnits(const SurfaceCacheSettings& settings) {
    const float texels = settings.paddingTexels / settings.texelsPerUnit;
    return texels > settings.minPaddingUnits ? texels : settings.minPaddingUnits;
}

// The most tiles a card side takes: maxCardTexels in whole tiles (at least one), or the atlas
// side when that is smaller.
inline uint32_t maxCardTilesIn(const SurfaceCacheSettings& settings) {
    const uint32_t atlasTiles = settings.atlasSize / kTileSize;
    const uint32_t cardTiles =
        settings.maxCardTexels / kTileSize > 0 ? settings.maxCardTexels / kTileSize : 1u;
    return cardTiles < atlasTiles ? cardTiles : atlasTiles;
}

} // namespace lumina::surface_cache
