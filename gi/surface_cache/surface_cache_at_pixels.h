#pragma once
// The surface cache as the camera sees it: for every GBuffer pixel, the final lighting of the
// card texel under it (the owner rule of card_bvh.h finds the card, its world-to-card map the
// texel). Against a path-traced image of the same view this measures the cache alone, before
// the screen probes gather it: `lumina render --dump-buffers` writes it as
// surface_cache_at_pixels.exr, and SurfaceCacheCornellGpu measures the Cornell boxes with it.
#include "gi/image/image.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lumina::surface_cache {

struct CacheAtPixels {
    image::Image radiance;    // R, G, B, and A: 1 where a card owns the pixel's surface, else 0
    uint32_t withoutCard = 0; // surface pixels no card owns (their radiance is 0)
};

// `position` and `normal` are the GBuffer's (normal A > 0 marks a surface); `finalLighting` the
// atlas's final layer, row by row, `atlasSize` texels a side.
CacheAtPixels cacheAtPixels(const image::Image& position, const image::Image& normal,
                            const std::vector<glm::vec4>& finalLighting, uint32_t atlasSize,
                            const std::vector<gpu::SurfaceCard>& cards);

} // namespace lumina::surface_cache
