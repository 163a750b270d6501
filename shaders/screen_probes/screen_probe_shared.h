#ifndef LUMINA_SCREEN_PROBE_SHARED_H
#define LUMINA_SCREEN_PROBE_SHARED_H
// Every constant and GPU struct of the screen-probe final gather (gi/screen_probes/,
// shaders/screen_probes/, docs/screen_probes.md), for C++ and HLSL.
#include "../common/camera_shared.h"
#include "../common/constants_shared.h"
#include "../common/sdf_scene_shared.h"
#include "../surface_cache/surface_cache_lighting_shared.h"
#include "octahedral_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

// Texels of one radiance map (LUMINA_SP_OCT_SIZE^2): the thread count of every per-probe pass.
#define LUMINA_SP_PROBE_TEXELS 64u
// Interior edge of a probe's irradiance tile (full octahedral, world space), and the tile with its
// one-texel border. 8 texels keep bilinear interpolation of irradiance within about 1% of the SH
// value at the probe normal (docs/screen_probes.md).
#define LUMINA_SP_IRRADIANCE_SIZE 8u
#define LUMINA_SP_IRRADIANCE_TILE 10u
// Rays per probe: the per-probe ray passes run one group of LUMINA_SP_PROBE_TEXELS threads per
// probe, each thread taking every 64th ray.
#define LUMINA_SP_MAX_RAYS 256u
// Thread-group edge of the full-resolution passes.
#define LUMINA_SP_SCREEN_GROUP LUMINA_SCREEN_GROUP_SIZE

// Cells (in world size at the probe's depth) a history probe may lie from the new one: the old
// cell centre is up to half a cell's diagonal from where the surface reprojects, plus rounding.
#define LUMINA_SP_HISTORY_MAX_CELLS 1.5f

// ScreenProbe::info.x
// World boxes where the scene changed since the last frame (a moved object's old and new place, a
// changed light's reach): history inside them keeps only a fraction of its weight.
#define LUMINA_SP_MAX_CHANGE_REGIONS 8u

#define LUMINA_SP_PROBE_VALID 1u
// ScreenProbeConstants::screen.w
#define LUMINA_SP_FLAG_PROBE_HISTORY 1u  // the previous frame's probes and radiance may be reused
#define LUMINA_SP_FLAG_SCREEN_HISTORY 2u // the previous frame's gathered irradiance may be reused
#define LUMINA_SP_FLAG_VOXEL_LIGHTING 4u // far-field hits read the voxel lighting volume
// The near field traced every ray this frame: the far field traces only its misses, from trace.w on.
#define LUMINA_SP_FLAG_NEAR_FIELD 8u
// The voxel lighting is the surface cache's (voxelGrid: rgb mean radiance, a coverage), read leaning
// along -normal (sampleVoxelLighting).
#define LUMINA_SP_FLAG_VOXEL_GRID 16u

// What the near field found along a ray: the a lane of the per-ray near-field result.
#define LUMINA_SP_NEAR_MISS 0u  // nothing within trace.w: the far field traces on
#define LUMINA_SP_NEAR_CARD 1u  // a hit, radiance from its card's final-lighting texels
#define LUMINA_SP_NEAR_VOXEL 2u // a hit no card covers, radiance from the voxel lighting

// Filtered coverage below which a lookup counts as empty (voxel lighting, card texels): a
// bilinear or trilinear weight this small means no covered texel lies within the footprint.
#define LUMINA_SP_MIN_COVERAGE 1e-3f

// ProbeRay::info.y
#define LUMINA_SP_STRATEGY_BRDF 0u
#define LUMINA_SP_STRATEGY_LIGHTING 1u

// One probe: where its cell's centre pixel saw a surface.
struct ScreenProbe {
    float4 positionAndDepth; // xyz: world position; w: view depth (along the camera's forward axis)
    float4 normal;           // xyz: unit world normal (the +z of probeFrame); w: 0
    uint4 info;              // x: LUMINA_SP_PROBE_VALID or 0 (sky: skipped by every later pass);
                             // y, z: the pixel it was placed at; w: 0
};

// One traced direction.
struct ProbeRay {
    float4 directionAndWeight; // xyz: unit world direction; w: balance-heuristic weight
                               // (probe_sampling_shared.h)
    uint4 info; // x: texel of the probe's radiance map; y: LUMINA_SP_STRATEGY_*; z: 1 if traced; w: 0
};

// Constants of every screen-probe kernel (register b1: b0 is the SDF scene's in the trace pass).
struct ScreenProbeConstants {
    GpuCamera camera;         // this frame
    GpuCamera previousCamera; // the frame the history was made in
    uint4 grid;               // x, y: probes across and down; z: spacing in pixels; w: probe count
    uint4 screen;             // x, y: image size; z: frame index (ray jitter); w: LUMINA_SP_FLAG_*
    uint4 rays;               // x: rays per probe; y: BRDF rays; z: lighting rays; w: 0
    float4 voxelMin;          // xyz: world corner of the voxel lighting volume
    float4 voxelMax;          // xyz: far corner
    float4 trace;             // x: max distance (world); y: tan of the cone half angle; z: origin bias
                              // (world, along the probe normal); w: near-field distance (world; 0 when
                              // the near field does not run)
    float4 temporal;          // x: probe history blend (weight of the new frame); y: outlier clamp (x the
                              // probe's history luminance); z: screen blend; w: lighting PDF floor
    float4 filter;            // x: plane-distance scale (x view depth); y: normal power; z: history plane
                              // tolerance (x view depth); w: cos of the history normal tolerance
    VoxelGridInfo voxelGrid;  // the surface cache's voxel lighting (near-field fallback; far hits with
                              // LUMINA_SP_FLAG_VOXEL_GRID); zero without a surface cache
    uint changeRegionCount;   // regions in use, at most LUMINA_SP_MAX_CHANGE_REGIONS
    uint changePadding0;
    uint changePadding1;
    uint changePadding2;
    float4 changeRegionMin[LUMINA_SP_MAX_CHANGE_REGIONS]; // xyz: world corner; w: history weight kept (0..1)
    float4 changeRegionMax[LUMINA_SP_MAX_CHANGE_REGIONS]; // xyz: far corner; w: 0
};

LUMINA_STATIC_ASSERT_SIZE(ScreenProbe, 48);
LUMINA_STATIC_ASSERT_SIZE(ProbeRay, 32);
LUMINA_STATIC_ASSERT_SIZE(ScreenProbeConstants, 720);

LUMINA_GPU_NAMESPACE_END

#endif
