#pragma once
// Combine (shaders/surface_cache/surface_cache_combine.hlsl): the final layer's outgoing
// radiance L = (E_direct + E_indirect) * albedo / pi + Le on the listed tiles. Emissive
// surfaces enter the GI here.
#include "gi/core/frame_context.h"
#include "gi/surface_cache/atlas_tile_list.h"
#include "gi/surface_cache/surface_cache_atlas.h"

namespace lumina::surface_cache {

class SurfaceCacheCombinePass {
public:
    static constexpr const char* kPassName = "surface cache: combine";

    // Records the pass over `tiles`, or a skip naming why when the list is empty.
    // `update` (the surface cache's update count) seeds the dither of the half rounding.
    void record(gi::FrameContext& frame, const SurfaceCacheAtlas& atlas, const AtlasTileList& tiles,
                uint32_t update) const;
};

} // namespace lumina::surface_cache
