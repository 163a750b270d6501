#pragma once
// Surface radiosity (shaders/surface_cache/radiosity.hlsl): one bounce of diffuse light between
// cached surfaces per update, on the listed tiles. Probes every 4x4 texels trace 16 rays
// through the global SDF, read the voxel lighting at their hits and project it to L1 SH; a
// 4-neighbour filter averages probes on the same card and plane; each texel integrates its
// probe's SH at its normal into the indirect layer (irradiance, negatives clamped). Rays that
// leave the scene read the sky.
#include "gi/core/frame_context.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/atlas_tile_list.h"
#include "gi/surface_cache/voxel_lighting_pass.h"

namespace lumina::surface_cache {

struct RadiosityTraceSettings {
    float originOffset = 0.0f; // rays start this far along the texel normal (world); 0: originOffsetVoxels
    // With originOffset 0: the lift in global-SDF voxels (finest cascade). The lift must clear the
    // open surfaces' shells, half a global voxel plus 0.6 of a mesh voxel thick, whose mesh part a
    // finer global SDF does not thin: GiSceneSettings keeps it at one voxel of a 64-voxel global
    // SDF (setGlobalSdfResolution, docs/gi.md energy 48.).
    float originOffsetVoxels = 1.0f;
    float maxDistance = 0.0f;     // world; 0: the global SDF grid's diagonal
    float filterMinCosine = 0.9f; // neighbours whose normals differ more are not filtered in
};

// Where probe rays start, off the surface along its normal (world units): the setting, or
// originOffsetVoxels global-SDF voxels. Whether a texel is buried does not depend on it (atlasTexelBuried
// looks two voxels ahead, surface_cache_texel.hlsli).
float radiosityOriginOffset(const RadiosityTraceSettings& settings, const sdf::SceneSdf& sdf);

class RadiosityPass {
public:
    static constexpr const char* kTracePassName = "surface cache: radiosity trace";
    static constexpr const char* kFilterPassName = "surface cache: radiosity filter";
    static constexpr const char* kIntegratePassName = "surface cache: radiosity integrate";

    // `sky` (the GpuScene's, gi/gpu_scene/sky_texture.h) is what rays leaving the scene see.
    RadiosityPass(rhi::IDevice& device, uint32_t atlasSize, const sdf::SceneSdf& sdf, rhi::TextureHandle sky,
                  const RadiosityTraceSettings& settings = {});

    // Zeroes the probes; record once before the first update.
    void recordClear(rhi::ICommandList& commands) const;
    // One bounce on the listed tiles; `rayPattern` picks the rays' pattern (RadiositySchedule::lastPass),
    // `blend` weighs the new trace against the probes' history (1: replace;
    // RadiositySchedule::lastBlend). Skips (with the reason) when the list is empty.
    void record(gi::FrameContext& frame, const AtlasSurfaceBindings& surfaces,
                const VoxelLightingPass& voxels, const AtlasTileList& tiles, uint32_t rayPattern,
                float blend = 1.0f) const;

    const rhi::BufferHandle& probes() const { return filtered_; }
    // The probes as the last trace left them, before the spatial filter.
    const rhi::BufferHandle& tracedProbes() const { return traced_; }
    // What the trace's rays found, summed since recordClear (RadiosityRayStats); reads it back
    // (waits for the device).
    gpu::RadiosityRayStats readRayStats(rhi::IDevice& device) const;

    // How far its rays reach (world): a change farther than this from a card does not reach it
    // in one bounce.
    float maxDistance() const { return maxDistance_; }

private:
    const sdf::SceneSdf& sdf_;
    rhi::TextureHandle sky_;
    float originOffset_ = 0.0f;
    float maxDistance_ = 0.0f;
    float filterMinCosine_ = 0.9f;
    rhi::BufferHandle traced_;   // RadiosityProbe per probe: the trace's SH
    rhi::BufferHandle filtered_; // RadiosityProbe per probe: after the spatial filter
    rhi::BufferHandle rayStats_; // RadiosityRayStats, summed by the trace
};

} // namespace lumina::surface_cache
