#pragma once
// Voxel lighting (shaders/surface_cache/voxel_lighting.hlsl): a 64^3 RGBA16F volume of the final
// layer's outgoing radiance over the scene bounds, rebuilt from the listed tiles each update:
// the low-frequency radiance that radiosity rays (and later far-field hits) read, through
// shaders/surface_cache/voxel_lighting_sampling.hlsli.
#include "gi/core/frame_context.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/atlas_tile_list.h"
#include "gi/surface_cache/surface_cache_atlas.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

#include <glm/glm.hpp>

namespace lumina::surface_cache {

// Where the cached surfaces are: the textures and buffers an atlas pass reads to find a
// texel's card and world position (shaders/surface_cache/surface_cache_texel.hlsli).
struct AtlasSurfaceBindings {
    const SurfaceCacheAtlas& atlas;
    rhi::TextureHandle tileOwner;    // R32_UINT tile-to-card lookup
    rhi::BufferHandle cards;         // StructuredBuffer<SurfaceCard>
    rhi::TextureHandle captureDepth; // D32: card-space z of each captured texel
};

// A cubic-voxel grid of `resolution`^3 over the box [boundsMin, boundsMax], one voxel of margin
// on every side so that surfaces on the bounds fall inside. Throws std::invalid_argument for an
// empty or non-finite box or a resolution below 4.
gpu::VoxelGridInfo voxelGridOver(glm::vec3 boundsMin, glm::vec3 boundsMax, uint32_t resolution);

class VoxelLightingPass {
public:
    static constexpr const char* kInjectPassName = "surface cache: voxel inject";
    static constexpr const char* kResolvePassName = "surface cache: voxel resolve";

    // Texels buried in other geometry (atlasTexelBuried, surface_cache_texel.hlsli) inject
    // nothing. Each texel weighs its world area over nominalTexelArea (a texel's
    // at the cache's full density): a voxel's radiance is the mean over the area it holds, not
    // over texels, whose density differs from card to card.
    VoxelLightingPass(rhi::IDevice& device, const gpu::VoxelGridInfo& grid, const sdf::SceneSdf& sdf,
                      float nominalTexelArea);

    // Zeroes the accumulator; record once before the first update.
    void recordClear(rhi::ICommandList& commands) const;
    // Injects the listed tiles' final radiance and resolves the volume; skips both (with the
    // reason) when the list is empty. `update` seeds the dither of the half rounding.
    void record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces, const AtlasTileList& tiles,
                uint32_t update) const;

    const gpu::VoxelGridInfo& grid() const { return grid_; }
    const rhi::TextureHandle& volume() const { return volume_; }

private:
    gpu::VoxelGridInfo grid_;
    const sdf::SceneSdf& sdf_;
    float nominalTexelArea_ = 1.0f;
    rhi::BufferHandle accumulator_; // per voxel face: r, g, b and weight in fixed point
    rhi::TextureHandle volume_; // RGBA16F, LUMINA_VOXEL_FACES x dims.x wide: rgb mean radiance, a coverage
};

} // namespace lumina::surface_cache
