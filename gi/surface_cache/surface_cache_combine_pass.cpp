#include "gi/surface_cache/surface_cache_combine_pass.h"

#include "shaders/common/constants_shared.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

namespace lumina::surface_cache {

void SurfaceCacheCombinePass::record(gi::FrameContext& frame, const SurfaceCacheAtlas& atlas,
                                     const AtlasTileList& tiles, uint32_t update) const {
    if (tiles.count() == 0) {
        frame.skip(kPassName, "no tiles to combine");
        return;
    }
    frame.compute(kPassName, "surface_cache/surface_cache_combine")
        .constants(gpu::AtlasTileListConstants{.atlasSize = atlas.size(),
                                               .tileCount = tiles.count(),
                                               .tilesPerRow = tiles.tilesPerRow(),
                                               .updateIndex = update})
        .read(0, atlas.albedo)
        .read(1, atlas.surface)
        .read(2, atlas.direct)
        .read(3, atlas.indirect)
        .read(4, tiles.buffer())
        .write(0, atlas.final)
        .dispatchThreads(tiles.threadsX(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         tiles.threadsY(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});
}

} // namespace lumina::surface_cache
