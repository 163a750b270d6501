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
// The most frames of history a probe's age counts (probe_temporal.hlsl): the spatial filter's share
// (1 - probeHistoryBlend)^age is below 1e-8 long before it.
#define LUMINA_SP_MAX_PROBE_AGE 1024u
// A value enters the unclamped mean at most this many times the ceiling: one poisoned frame (a
// light 1e6 times too bright) must not lift the ceiling for a hundred frames, nor a firefly for ten.
// Measured on lavapipe (docs/gi.md, energy 40.): at 16 the static Cornell box flickered (frame to
// frame relMSE up to 1.27e-3); at 2 the mean's own cap brought the dark states back (two runs 30 %
// apart after 150 frames of a flickering sky); at 4 steady (6.1e-4) and both runs the same within
// 300 frames.
#define LUMINA_SP_UNCLAMPED_CAP 4.0f

// World boxes where the scene changed since the last frame (a moved object's old and new place, a
// changed light's reach): history inside them keeps only a fraction of its weight.
#define LUMINA_SP_MAX_CHANGE_REGIONS 8u

// ScreenProbe::info.x
#define LUMINA_SP_PROBE_VALID 1u

// Adaptive probes (probe_adaptive_placement.hlsl): a pixel whose best corner probe of the uniform grid
// has a surface weight below this lies on no probe's surface; its adaptive tile gets a probe of its own.
#define LUMINA_SP_ADAPTIVE_COVERAGE 0.25f
// An adaptive tile's entry in the adaptive index (and its candidate) when it has no probe.
#define LUMINA_SP_NO_ADAPTIVE_PROBE 0xffffffffu
// A run of adaptive tiles: this many of one row. Placement takes a run per group, a thread per tile,
// and counts the run's candidates; allocation takes a row per group and numbers it a run at a time.
#define LUMINA_SP_ADAPTIVE_RUN 64u

// ScreenProbeConstants::flags
#define LUMINA_SP_FLAG_PROBE_HISTORY 1u  // the previous frame's probes and radiance may be reused
#define LUMINA_SP_FLAG_SCREEN_HISTORY 2u // the previous frame's gathered irradiance may be reused
#define LUMINA_SP_FLAG_VOXEL_LIGHTING 4u // far-field hits read the voxel lighting volume
// The near field traced every ray this frame: the far field traces only its misses, from nearFieldDistance
// on.
#define LUMINA_SP_FLAG_NEAR_FIELD 8u
// The voxel lighting is the surface cache's (voxelGrid: rgb mean radiance, a coverage), read leaning
// along -normal (sampleVoxelLighting).
#define LUMINA_SP_FLAG_VOXEL_GRID 16u

// What the near field found along a ray: the a lane of the per-ray near-field result.
#define LUMINA_SP_NEAR_MISS 0u  // nothing within nearFieldDistance: the far field traces on
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

// A world box where the scene changed (ScreenProbeConstants::changeRegions).
struct ChangeRegion {
    float3 boxMin;
    float historyKept; // weight history inside the box keeps (0..1)
    float3 boxMax;
    float boxMaxPadding;
};

// Constants of every screen-probe kernel (register b1: b0 is the SDF scene's in the trace pass).
struct ScreenProbeConstants {
    GpuCamera camera;         // this frame
    GpuCamera previousCamera; // the frame the history was made in
    // The probe grid.
    uint2 probeGrid;   // probes across and down
    uint probeSpacing; // pixels between probe centres (a cell's edge)
    uint probeCount;   // every probe slot: the uniform grid's, then the adaptive rows' (probeGrid.x wide)
    // The image and the frame.
    uint2 imageSize; // pixels
    uint frameIndex; // jitters the ray directions from frame to frame
    uint flags;      // LUMINA_SP_FLAG_*
    // Rays per probe.
    uint raysPerProbe;
    uint brdfRays;     // drawn from the BRDF PDF
    uint lightingRays; // drawn from the lighting PDF (raysPerProbe - brdfRays)
    // Free space a ray start keeps when it slides onto its probe's line (probeRayStart), in the
    // finest global SDF voxels: half the origin push's clearance, a quarter of the origin bias.
    float slideMarginVoxels;
    // The voxel lighting volume that far-field hits read.
    float3 voxelMin; // world corner
    float voxelMinPadding;
    float3 voxelMax; // far corner
    float voxelMaxPadding;
    // Tracing (world distances).
    float maxTraceDistance;
    float coneTanHalfAngle;  // tan of the cone half angle
    float originBias;        // along the probe normal
    float nearFieldDistance; // the far field starts here; 0 when the near field does not run
    // Temporal reuse.
    float probeHistoryBlend;  // weight of the new frame in the probe history
    float outlierClamp;       // x the probe's history luminance
    float screenHistoryBlend; // weight of the new frame in the gathered irradiance's history
    float lightingPdfFloor;   // share of the lighting PDF spread uniformly
    // Filters and history acceptance.
    float filterPlaneScale;       // plane-distance scale (x view depth)
    float filterNormalPower;      // exponent of the normal weight
    float historyPlaneTolerance;  // x view depth
    float historyNormalTolerance; // cos of the largest normal change history survives
    VoxelGridInfo voxelGrid;      // the surface cache's voxel lighting (near-field fallback; far hits with
                                  // LUMINA_SP_FLAG_VOXEL_GRID); zero without a surface cache
    uint changeRegionCount;       // regions in use, at most LUMINA_SP_MAX_CHANGE_REGIONS
    float outlierClampTexelShare; // the outlier clamp's share of a texel's unclamped mean
                                  // (ScreenProbeSettings), here to keep the layout
    uint uniformProbeCount;       // probeGrid.x * probeGrid.y: adaptive probes' slots start here
    uint adaptiveSpacing;         // pixels per adaptive tile edge (probeSpacing / 2); 0: no adaptive probes
    ChangeRegion changeRegions[LUMINA_SP_MAX_CHANGE_REGIONS];
};

LUMINA_STATIC_ASSERT_SIZE(ChangeRegion, 32);
LUMINA_STATIC_ASSERT_SIZE(ScreenProbe, 48);
LUMINA_STATIC_ASSERT_SIZE(ProbeRay, 32);
LUMINA_STATIC_ASSERT_SIZE(ScreenProbeConstants, 720);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, probeGrid, 288);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, imageSize, 304);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, raysPerProbe, 320);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, voxelMin, 336);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, voxelMax, 352);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, maxTraceDistance, 368);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, probeHistoryBlend, 384);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, filterPlaneScale, 400);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, voxelGrid, 416);
LUMINA_STATIC_ASSERT_OFFSET(ScreenProbeConstants, changeRegions, 464);

LUMINA_GPU_NAMESPACE_END

#endif
