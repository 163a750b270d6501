#pragma once
// What the screen probes read of a surface cache (docs/surface_cache.md): the near field looks up
// the card that owns a hit and reads its final lighting; the voxel lighting stands in where no
// card does, and lights far-field hits when the caller gives no volume of its own. Handles, not
// the cache, so that anything holding these resources can be read; fill it from a SurfaceCache
// with surfaceCacheView():
//
//   probes.record(frame, {..., .surfaceCache = gi::surfaceCacheView(cache)});
#include "rhi/rhi.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

namespace lumina::surface_cache {
class SurfaceCache;
}

namespace lumina::gi {

struct SurfaceCacheView {
    rhi::TextureHandle finalLighting; // RGBA16F Texture2D atlas: outgoing radiance, a = 1 where captured
    rhi::BufferHandle cards;          // StructuredBuffer<SurfaceCard>
    rhi::BufferHandle cardBvh;        // StructuredBuffer<CardBvhNode> over those cards
    rhi::TextureHandle voxelLighting; // RGBA16F 3D over voxelGrid, LUMINA_VOXEL_FACES face columns
                                      // side by side along x: rgb mean radiance, a = coverage
    gpu::VoxelGridInfo voxelGrid{};
};

// The cache's final layer, cards, card BVH and voxel lighting.
SurfaceCacheView surfaceCacheView(const surface_cache::SurfaceCache& cache);

// Throws std::invalid_argument naming the first missing resource or bad format.
void checkSurfaceCacheView(const SurfaceCacheView& view);

} // namespace lumina::gi
