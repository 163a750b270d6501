#include "gi/surface_cache/radiosity_pass.h"

#include "rhi/transfer.h"
#include "shaders/common/constants_shared.h"

#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <utility>

namespace lumina::surface_cache {
// By default rays start one global-SDF voxel off the surface at the presets' 64 voxels: the sphere
// tracer stops within a tenth of a voxel of a surface (its hit threshold), and the origin's own
// clearance (half a voxel, pushed along the gradient in radiosity.hlsl) keeps it off the walls
// beside it. Two voxels, as before that clearance existed, showed a floor probe by a wall the room
// from 26 cm up in two_rooms and brightened it by 4.5 % (docs/gi.md, energy, 16.).
float radiosityOriginOffset(const RadiosityTraceSettings& settings, const sdf::SceneSdf& sdf) {
    return settings.originOffset > 0.0f ? settings.originOffset
                                        : settings.originOffsetVoxels * sdf.sceneInfo().globalVoxelSize;
}

RadiosityPass::RadiosityPass(rhi::IDevice& device, uint32_t atlasSize, const sdf::SceneSdf& sdf,
                             rhi::TextureHandle sky, const RadiosityTraceSettings& settings)
    : sdf_(sdf), sky_(std::move(sky)), filterMinCosine_(settings.filterMinCosine) {
    if (atlasSize == 0 || atlasSize % LUMINA_ATLAS_TILE_SIZE != 0) {
        throw std::invalid_argument("radiosity: atlas size " + std::to_string(atlasSize) +
                                    " is not a positive multiple of 64");
    }
    if (!(settings.originOffset >= 0.0f) || !(settings.originOffsetVoxels > 0.0f) ||
        !(settings.maxDistance >= 0.0f) ||
        !(settings.filterMinCosine >= -1.0f && settings.filterMinCosine <= 1.0f)) {
        throw std::invalid_argument(
            "radiosity: origin offset " + std::to_string(settings.originOffset) + " (" +
            std::to_string(settings.originOffsetVoxels) + " voxels)" + ", max distance " +
            std::to_string(settings.maxDistance) + " and filter cosine " +
            std::to_string(settings.filterMinCosine) +
            ": offsets and distances must be >= 0 (voxels > 0), the cosine within [-1, 1]");
    }
    const gpu::SdfSceneInfo info = sdf.sceneInfo();
    originOffset_ = radiosityOriginOffset(settings, sdf);
    maxDistance_ =
        settings.maxDistance > 0.0f ? settings.maxDistance : glm::length(info.globalMax - info.globalMin);
    const uint64_t probesPerSide = atlasSize / LUMINA_RADIOSITY_PROBE_SPACING;
    const rhi::BufferDesc desc{.size = probesPerSide * probesPerSide * sizeof(gpu::RadiosityProbe),
                               .structStride = sizeof(gpu::RadiosityProbe),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "surface cache radiosity probes (traced)"};
    traced_ = device.createBuffer(desc);
    rhi::BufferDesc filteredDesc = desc;
    filteredDesc.debugName = "surface cache radiosity probes (filtered)";
    filtered_ = device.createBuffer(filteredDesc);
    rayStats_ = device.createBuffer({.size = sizeof(gpu::RadiosityRayStats),
                                     .structStride = sizeof(uint32_t),
                                     .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                     .debugName = "surface cache radiosity ray stats"});
}

void RadiosityPass::recordClear(rhi::ICommandList& commands) const {
    commands.fillBuffer(*traced_, 0);
    commands.fillBuffer(*filtered_, 0);
    commands.fillBuffer(*rayStats_, 0);
}

gpu::RadiosityRayStats RadiosityPass::readRayStats(rhi::IDevice& device) const {
    return rhi::readBufferAs<gpu::RadiosityRayStats>(device, *rayStats_).at(0);
}

void RadiosityPass::record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces,
                           const VoxelLightingPass& voxels, const AtlasTileList& tiles, uint32_t rayPattern,
                           float blend) const {
    if (tiles.count() == 0) {
        for (const char* pass : {kTracePassName, kFilterPassName, kIntegratePassName}) {
            frame.skip(pass, "no tiles to update");
        }
        return;
    }
    const gpu::RadiosityConstants constants{.grid = voxels.grid(),
                                            .atlasSize = surfaces.atlas.size(),
                                            .tileCount = tiles.count(),
                                            .tilesPerRow = tiles.tilesPerRow(),
                                            .updateIndex = rayPattern,
                                            .originOffset = originOffset_,
                                            .maxDistance = maxDistance_,
                                            .filterMinCosine = filterMinCosine_,
                                            .temporalBlend = blend};
    const auto bindSurfaces = [&](gi::ComputePass& pass) -> gi::ComputePass& {
        return pass.constants(constants)
            .read(6, surfaces.atlas.surface)
            .read(7, surfaces.tileOwner)
            .read(8, surfaces.cards)
            .read(9, surfaces.captureDepth)
            .read(10, tiles.buffer());
    };
    const uint32_t probesPerTile = LUMINA_PROBES_PER_TILE;
    gi::ComputePass trace = frame.compute(kTracePassName, "surface_cache/radiosity.trace");
    sdf_.bindForTracing(bindSurfaces(trace))
        .read(11, voxels.volume())
        .read(13, sky_)
        .write(0, traced_)
        .write(2, rayStats_)
        .dispatchThreads(tiles.threadsX(probesPerTile), tiles.threadsY(probesPerTile),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});

    gi::ComputePass filter = frame.compute(kFilterPassName, "surface_cache/radiosity.filter");
    sdf_.bindForTracing(bindSurfaces(filter)) // neighbours are blended only where in sight
        .read(12, traced_)
        .write(0, filtered_)
        .dispatchThreads(tiles.threadsX(probesPerTile), tiles.threadsY(probesPerTile),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});

    gi::ComputePass integrate = frame.compute(kIntegratePassName, "surface_cache/radiosity.integrate");
    bindSurfaces(integrate)
        .read(12, filtered_)
        .write(1, surfaces.atlas.indirect)
        .dispatchThreads(tiles.threadsX(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         tiles.threadsY(LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE),
                         {LUMINA_LINEAR_GROUP_SIZE, 1});
}

} // namespace lumina::surface_cache
