#include "gi/surface_cache/surface_cache_direct_light_pass.h"

#include "shaders/common/constants_shared.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

#include <stdexcept>
#include <string>

namespace lumina::surface_cache {

void SurfaceCacheDirectLightPass::record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces,
                                         const gi::ShadowedLights& lights, const AtlasTileList& tiles) const {
    if (tiles.count() == 0) {
        frame.skip(kPassName, "no tiles to light");
        return;
    }
    const char* missing = !lights.shadowConstants   ? "shadow constants"
                          : !lights.lights          ? "light buffer"
                          : !lights.sunShadowMap    ? "sun shadow map"
                          : !lights.pointShadowMaps ? "point shadow maps"
                                                    : nullptr;
    if (missing) {
        throw std::invalid_argument(std::string(kPassName) + ": the deferred renderer's " + missing +
                                    " is missing (render a frame first)");
    }
    // The kernel addresses cube faces itself (cubeFaceOf / cubeFaceUv) and reads them as layers,
    // as the deferred direct light does.
    rhi::BindingSetItem pointMaps = rhi::BindingSetItem::sampledTexture(1, lights.pointShadowMaps);
    pointMaps.overrideDimension = true;
    pointMaps.viewDimension = rhi::TextureDimension::Texture2DArray;
    frame.compute(kPassName, "surface_cache/surface_cache_direct_light")
        .constants(gpu::SurfaceDirectLightConstants{.atlasSize = surfaces.atlas.size(),
                                                    .tileCount = tiles.count(),
                                                    .tilesPerRow = tiles.tilesPerRow(),
                                                    .lightCount = lights.lightCount})
        .constantBuffer(0, lights.shadowConstants)
        .read(0, lights.sunShadowMap)
        .bind(pointMaps)
        .read(2, lights.lights)
        .read(3, surfaces.atlas.surface)
        .read(4, surfaces.tileOwner)
        .read(5, surfaces.cards)
        .read(6, surfaces.captureDepth)
        .read(7, tiles.buffer())
        .write(0, surfaces.atlas.direct)
        .dispatchThreads(tiles.threadsX(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         tiles.threadsY(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});
}

} // namespace lumina::surface_cache
