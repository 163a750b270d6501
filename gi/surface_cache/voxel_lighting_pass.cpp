#include "gi/surface_cache/voxel_lighting_pass.h"

#include "shaders/common/constants_shared.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {

gpu::VoxelGridInfo voxelGridOver(glm::vec3 boundsMin, glm::vec3 boundsMax, uint32_t resolution) {
    const glm::vec3 extent = boundsMax - boundsMin;
    const float largest = std::max(extent.x, std::max(extent.y, extent.z));
    const bool finite = !glm::any(glm::isnan(boundsMin)) && !glm::any(glm::isinf(boundsMin)) &&
                        !glm::any(glm::isnan(boundsMax)) && !glm::any(glm::isinf(boundsMax));
    if (!finite || !(largest > 0.0f) || extent.x < 0.0f || extent.y < 0.0f || extent.z < 0.0f) {
        throw std::invalid_argument("voxel lighting: bounds of extent (" + std::to_string(extent.x) + ", " +
                                    std::to_string(extent.y) + ", " + std::to_string(extent.z) +
                                    ") hold no finite volume");
    }
    if (resolution < 4) {
        throw std::invalid_argument("voxel lighting: resolution " + std::to_string(resolution) +
                                    " is below 4");
    }
    // resolution - 2 voxels span the bounds' longest side; one voxel of margin on each side.
    const float voxel = largest / float(resolution - 2);
    const glm::vec3 centre = 0.5f * (boundsMin + boundsMax);
    const glm::vec3 origin = centre - 0.5f * voxel * float(resolution);
    return {.boxMin = origin, .voxelSize = voxel, .dims = glm::uvec3(resolution), .dimsPadding = 0};
}

VoxelLightingPass::VoxelLightingPass(rhi::IDevice& device, const gpu::VoxelGridInfo& grid,
                                     const sdf::SceneSdf& sdf, float nominalTexelArea)
    : grid_(grid), sdf_(sdf), nominalTexelArea_(nominalTexelArea) {
    if (!(nominalTexelArea > 0.0f) || !std::isfinite(nominalTexelArea)) {
        throw std::invalid_argument("voxel lighting: nominal texel area " + std::to_string(nominalTexelArea) +
                                    " is not a positive finite number");
    }
    const uint64_t voxels = uint64_t(grid.dims.x) * grid.dims.y * grid.dims.z;
    accumulator_ = device.createBuffer({.size = voxels * LUMINA_VOXEL_FACES * 4 * sizeof(uint32_t),
                                        .structStride = sizeof(uint32_t),
                                        .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                        .debugName = "surface cache voxel accumulator"});
    volume_ = device.createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                    .format = rhi::Format::RGBA16_FLOAT,
                                    .width = grid.dims.x * LUMINA_VOXEL_FACES,
                                    .height = grid.dims.y,
                                    .depth = grid.dims.z,
                                    .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage,
                                    .debugName = "surface cache voxel lighting"});
}

void VoxelLightingPass::recordClear(rhi::ICommandList& commands) const {
    commands.fillBuffer(*accumulator_, 0);
    commands.clearColor(*volume_, {0.0f, 0.0f, 0.0f, 0.0f});
}

void VoxelLightingPass::record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces,
                               const AtlasTileList& tiles, uint32_t update) const {
    if (tiles.count() == 0) {
        frame.skip(kInjectPassName, "no tiles to inject");
        frame.skip(kResolvePassName, "no tiles to inject");
        return;
    }
    const gpu::VoxelInjectConstants constants{.grid = grid_,
                                              .atlasSize = surfaces.atlas.size(),
                                              .tileCount = tiles.count(),
                                              .tilesPerRow = tiles.tilesPerRow(),
                                              .updateIndex = update,
                                              .nominalTexelArea = nominalTexelArea_,
                                              .injectPadding0 = 0.0f,
                                              .injectPadding1 = 0.0f,
                                              .injectPadding2 = 0.0f};
    sdf_.bindForTracing(frame.compute(kInjectPassName, "surface_cache/voxel_lighting.inject"))
        .constants(constants)
        .read(6, surfaces.atlas.final)
        .read(7, surfaces.atlas.surface)
        .read(8, surfaces.tileOwner)
        .read(9, surfaces.cards)
        .read(10, surfaces.captureDepth)
        .read(11, tiles.buffer())
        .write(0, accumulator_)
        .write(1, volume_)
        .dispatchThreads(tiles.threadsX(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         tiles.threadsY(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});
    frame.compute(kResolvePassName, "surface_cache/voxel_lighting.resolve")
        .constants(constants)
        .write(0, accumulator_)
        .write(1, volume_)
        .dispatchThreads(grid_.dims.x * LUMINA_VOXEL_FACES, grid_.dims.y, grid_.dims.z,
                         {LUMINA_VOLUME_GROUP_SIZE, LUMINA_VOLUME_GROUP_SIZE, LUMINA_VOLUME_GROUP_SIZE});
}

} // namespace lumina::surface_cache
