#ifndef LUMINA_DDGI_SHARED_H
#define LUMINA_DDGI_SHARED_H
// DDGI probe volumes (docs/ddgi.md), shared by C++ (gi/ddgi/, tests) and HLSL (shaders/ddgi/).
//
// Every volume of a technique lives in one set of buffers and atlases: probe p of volume v has
// the global index volumes[v].firstProbe + p, with p = x + counts.x * (y + counts.y * z). Its
// octahedral tiles sit in the atlases at column p % (counts.x * counts.y) and row
// volumes[v].firstTileRow + p / (counts.x * counts.y): one row of tiles per z plane.
#include "../common/constants_shared.h"
#include "../common/shared_types.h"
#include "../surface_cache/surface_cache_lighting_shared.h"

#ifdef __cplusplus
namespace lumina::gpu {
inline float ddgi_frac(float x) {
    return x - std::floor(x);
}
} // namespace lumina::gpu
#define LUMINA_DDGI_FRAC ddgi_frac
#else
#define LUMINA_DDGI_FRAC frac
#endif

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_DDGI_MAX_VOLUMES 4u
// Interior texels per side of a probe's irradiance and distance tiles; each tile has a one-texel
// border that repeats the interior across the octahedral seams (bilinear lookups never leave it).
#define LUMINA_DDGI_IRRADIANCE_SIZE 8u
#define LUMINA_DDGI_IRRADIANCE_TILE (LUMINA_DDGI_IRRADIANCE_SIZE + 2u)
#define LUMINA_DDGI_DISTANCE_SIZE 16u
#define LUMINA_DDGI_DISTANCE_TILE (LUMINA_DDGI_DISTANCE_SIZE + 2u)
// The first rays of every probe go in these fixed directions (no rotation), so relocation and
// classification judge the same set every update; they are left out of the blends.
#define LUMINA_DDGI_FIXED_RAYS 32u
#define LUMINA_DDGI_MAX_RAYS 256u
// Threads of the per-probe trace and of the per-probe thread passes.
#define LUMINA_DDGI_TRACE_GROUP LUMINA_LINEAR_GROUP_SIZE
#define LUMINA_DDGI_PROBE_GROUP LUMINA_LINEAR_GROUP_SIZE
#define LUMINA_DDGI_SAMPLE_GROUP LUMINA_SCREEN_GROUP_SIZE

// Irradiance is stored as E^(1 / LUMINA_DDGI_IRRADIANCE_GAMMA) in RGBA16F: a half float tops out
// at 65504, which a point light's irradiance in millimetre scenes exceeds; the fifth root keeps
// every finite float's range (65504^5 ~ 1e24) at a relative precision of 5 x 2^-11 (0.25%).
#define LUMINA_DDGI_IRRADIANCE_GAMMA 5.0f

// Probe states (DdgiProbe.offsetAndState.w).
#define LUMINA_DDGI_PROBE_FRESH 0.0f    // active, no history yet: the next blend takes the update whole
#define LUMINA_DDGI_PROBE_ACTIVE 1.0f   // active, with history
#define LUMINA_DDGI_PROBE_INACTIVE 2.0f // classified off: only its fixed rays are traced, never blended

// Per-volume flags (DdgiVolumeInfo::flags).
#define LUMINA_DDGI_VOLUME_RESET 1u // the reset pass returns all its probes to FRESH at offset 0

struct DdgiProbe {
    float4 offsetAndState; // xyz: world offset from the lattice point (relocation); w: LUMINA_DDGI_PROBE_*
};
LUMINA_STATIC_ASSERT_SIZE(DdgiProbe, 16);

struct DdgiVolumeInfo {
    float3 origin;      // world position of lattice point (0, 0, 0)
    float distanceUnit; // the largest spacing: stored distances are in these units
    float3 spacing;     // world distance between lattice points
    float maxOffset;    // how far relocation may move a probe (fraction of a cell per axis)
    uint3 counts;       // probes per axis
    uint firstProbe;    // global index of the volume's first probe
    uint tilesPerRow;   // atlas tiles per row (counts.x * counts.y)
    uint firstTileRow;  // the volume's first row of atlas tiles
    uint flags;         // LUMINA_DDGI_VOLUME_*
    uint probeCount;    // counts.x * counts.y * counts.z
    // A cascade scrolls with the camera: lattice point c (its place, from the volume's origin) is
    // stored in probe slot (c + scroll) mod counts, so a move by whole cells keeps every probe
    // that stays inside where it is. Those whose lattice coordinate on some axis lies in
    // [enteredMin, enteredMax) of that axis entered the volume with this update's move and are
    // reset (enteredMin = enteredMax: none on that axis).
    uint3 scroll; // slot offset
    uint scrollPadding;
    uint3 enteredMin;
    uint enteredMinPadding;
    uint3 enteredMax;
    uint enteredMaxPadding;
};
LUMINA_STATIC_ASSERT_SIZE(DdgiVolumeInfo, 112);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, spacing, 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, counts, 32);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, tilesPerRow, 48);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, scroll, 64);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, enteredMin, 80);
LUMINA_STATIC_ASSERT_OFFSET(DdgiVolumeInfo, enteredMax, 96);

struct DdgiConstants {
    DdgiVolumeInfo volumes[LUMINA_DDGI_MAX_VOLUMES];
    float4 rotation[3]; // rows of this update's random rotation of the blended rays
    // Rays and probes.
    uint raysPerProbe;
    uint fixedRays; // the first rays of every probe, never rotated (classification, relocation)
    uint volumeCount;
    uint probeCount; // over every volume
    // Tracing (world distances unless said).
    float nearFieldDistance;
    float maxTraceDistance;
    float backfaceFraction;     // of the fixed rays: more back-face hits marks a probe inside geometry
    float minFrontfaceDistance; // closest front face allowed (fraction of a cell)
    // Blending.
    float hysteresis;
    float changedHysteresis; // hysteresis after a large change
    float largeChangeRatio;  // ratio between old and new that is a large change
    float distanceSharpness; // exponent of the cosine weighting distances
    // Sampling and probe maintenance.
    float normalBias;          // fraction of a volume's smallest spacing
    float viewBias;            // fraction of a volume's smallest spacing
    uint relocation;           // 1: relocation on
    uint classification;       // 1: classification on
    uint2 irradianceAtlasSize; // texels
    uint2 distanceAtlasSize;   // texels
    float3 cameraPosition;     // view bias
    float cameraPadding;
    uint2 imageSize;
    uint imagePadding0;
    uint imagePadding1;
    VoxelGridInfo voxelGrid; // the surface cache's voxel lighting, for hits no card owns
};
LUMINA_STATIC_ASSERT_SIZE(DdgiConstants, 4 * 112 + 3 * 16 + 7 * 16 + 32);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, raysPerProbe, 4 * 112 + 3 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, nearFieldDistance, 4 * 112 + 4 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, hysteresis, 4 * 112 + 5 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, normalBias, 4 * 112 + 6 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, irradianceAtlasSize, 4 * 112 + 7 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, distanceAtlasSize, 4 * 112 + 7 * 16 + 8);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, cameraPosition, 4 * 112 + 8 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, imageSize, 4 * 112 + 9 * 16);
LUMINA_STATIC_ASSERT_OFFSET(DdgiConstants, voxelGrid, 4 * 112 + 10 * 16);

// Unit direction k of n spread over the sphere on a spherical Fibonacci spiral: z steps evenly
// from 1 to -1 (equal areas), the azimuth turns by the golden angle.
LUMINA_INLINE float3 ddgiFibonacciDirection(uint k, uint n) {
    const float goldenRatioFraction = 0.618033988749895f; // (sqrt(5) - 1) / 2
    const float z = 1.0f - (2.0f * float(k) + 1.0f) / float(n);
    const float r = sqrt(max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * LUMINA_PI * LUMINA_DDGI_FRAC(float(k) * goldenRatioFraction);
    return float3(r * cos(phi), r * sin(phi), z);
}

// Slot coordinates of probe p (local to its volume).
LUMINA_INLINE uint3 ddgiProbeCoord(uint p, uint3 counts) {
    const uint plane = counts.x * counts.y;
    return uint3(p % counts.x, (p % plane) / counts.x, p / plane);
}

LUMINA_INLINE uint ddgiProbeIndex(uint3 c, uint3 counts) {
    return c.x + counts.x * (c.y + counts.y * c.z);
}

// The lattice point a slot holds, and the slot of a lattice point (scrolled cascades).
LUMINA_INLINE uint3 ddgiLatticeOfSlot(DdgiVolumeInfo v, uint3 slot) {
    return (slot + v.counts - v.scroll) % v.counts;
}

LUMINA_INLINE uint3 ddgiSlotOfLattice(DdgiVolumeInfo v, uint3 lattice) {
    return (lattice + v.scroll) % v.counts;
}

LUMINA_INLINE float3 ddgiLatticePosition(DdgiVolumeInfo v, uint3 c) {
    return float3(v.origin.x + v.spacing.x * float(c.x), v.origin.y + v.spacing.y * float(c.y),
                  v.origin.z + v.spacing.z * float(c.z));
}

// The top-left texel of probe p's tile in an atlas of `tile`-texel tiles.
LUMINA_INLINE uint2 ddgiTileOrigin(DdgiVolumeInfo v, uint p, uint tile) {
    return uint2((p % v.tilesPerRow) * tile, (v.firstTileRow + p / v.tilesPerRow) * tile);
}

LUMINA_INLINE float ddgiEncodeIrradiance(float e) {
    return pow(max(e, 0.0f), 1.0f / LUMINA_DDGI_IRRADIANCE_GAMMA);
}

LUMINA_INLINE float ddgiDecodeIrradiance(float stored) {
    const float s2 = stored * stored;
    return s2 * s2 * stored; // stored^5
}

LUMINA_GPU_NAMESPACE_END

#endif
