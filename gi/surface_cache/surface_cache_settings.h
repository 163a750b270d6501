#pragma once
// What a scene's surface cache is built with: atlas size, card resolution and card generation.
// Lengths are in scene units (gi/scene/units.h), so texelsPerUnit depends on the scene's scale:
// 1 texel per unit is 1 mm texels in the Cornell box (millimetres).
#include "gi/surface_cache/tile_allocator.h"

#include <cstdint>

namespace lumina::surface_cache {

struct SurfaceCacheSettings {
    uint32_t atlasSize = 4096;    // texels per side of every atlas layer; a multiple of 64
    float texelsPerUnit = 1.0f;   // card texel density before rounding up to whole tiles
    uint32_t maxCardTiles = 16;   // a card side never exceeds this many tiles (1024 texels):
                                  // large surfaces get a lower density instead of filling the atlas
                                  // (and never more than the atlas side)
    float paddingTexels = 2.0f;   // card bounds grow by this many texels (1/texelsPerUnit each)...
    float minPaddingUnits = 0.0f; // ...or by this much in scene units, whichever is larger: SDF hits
                                  // lie off the surface by up to about half a mesh-SDF voxel (open
                                  // surfaces, docs/sdf.md), so a renderer sets this to that voxel size
                                  // for the hits to find their cards
    uint32_t maxCardsPerAxis = 4; // depth layers per mesh axis direction before the deepest merge
    float layerGap = 0.1f;        // a gap along the axis wider than this fraction of the mesh's extent
                                  // starts a new depth layer (see mesh_cards.h)
};

// Throws std::invalid_argument naming the first setting out of range.
void validate(const SurfaceCacheSettings& settings);

// The padding of card bounds in scene units.
inline float paddingUnits(const SurfaceCacheSettings& settings) {
    const float texels = settings.paddingTexels / settings.texelsPerUnit;
    return texels > settings.minPaddingUnits ? texels : settings.minPaddingUnits;
}

// The most tiles a card side takes: maxCardTiles, or the atlas side when that is smaller.
inline uint32_t maxCardTilesIn(const SurfaceCacheSettings& settings) {
    const uint32_t atlasTiles = settings.atlasSize / kTileSize;
    return settings.maxCardTiles < atlasTiles ? settings.maxCardTiles : atlasTiles;
}

} // namespace lumina::surface_cache
