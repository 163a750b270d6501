#pragma once
// Direct light of the atlas (shaders/surface_cache/surface_cache_direct_light.hlsl): the
// irradiance of the deferred renderer's lights, through its shadow maps, at every texel of the
// listed tiles (one thread per texel, the card from the tile-to-card lookup).
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/surface_cache/atlas_tile_list.h"
#include "gi/surface_cache/voxel_lighting_pass.h"

namespace lumina::surface_cache {

class SurfaceCacheDirectLightPass {
public:
    static constexpr const char* kPassName = "surface cache: direct light";

    // Records the pass over `tiles`, or a skip naming why when the list is empty. Throws
    // std::invalid_argument naming what is missing when `lights` lacks a buffer or map.
    void record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces,
                const gi::ShadowedLights& lights, const AtlasTileList& tiles) const;
};

} // namespace lumina::surface_cache
