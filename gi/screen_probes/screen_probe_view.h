#pragma once
// What the passes of one frame see: the resources, which half of each ping-pong pair is this
// frame's, and the inputs from outside (GBuffer, scene SDFs, voxel lighting, surface cache).
#include "gi/deferred/gbuffer_pass.h"
#include "gi/screen_probes/screen_probe_resources.h"
#include "gi/screen_probes/surface_cache_view.h"
#include "gi/sdf/scene_sdf.h"

#include <cstdint>

namespace lumina::gi {

struct ScreenProbeView {
    const ScreenProbeResources& resources;
    const GBuffer& gbuffer;
    const sdf::SceneSdf& sdf;
    rhi::TextureHandle voxelLighting;               // never null (ScreenProbeResources::noVoxelLighting)
    const SurfaceCacheView* surfaceCache = nullptr; // null: none given (no near field)
    rhi::TextureHandle sky;                         // what misses see (ScreenProbeInputs::sky)
    uint32_t current = 0;                           // index into the ping-pong pairs

    uint32_t previous() const { return current ^ 1u; }
    // Per-probe passes: one group of 64 threads per probe slot, over the grid and the adaptive rows.
    uint32_t groupsX() const { return resources.gridWidth; }
    uint32_t groupsY() const { return resources.probeRows(); }
};

} // namespace lumina::gi
