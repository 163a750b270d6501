#ifndef LUMINA_SURFACE_CACHE_LIGHTING_SHARED_H
#define LUMINA_SURFACE_CACHE_LIGHTING_SHARED_H
// GPU layouts of the surface cache's lighting passes (combine, voxel lighting, radiosity;
// gi/surface_cache/, docs/surface_cache.md), shared by C++ and HLSL.
//
// Units: the direct and indirect layers hold irradiance E (W/m^2 in the scene's units, no
// albedo); the final layer holds outgoing radiance L = (E_direct + E_indirect) * albedo / pi
// + Le, which is what ray hits and the voxel lighting read.
#include "../common/shared_types.h"

// Atlas texels per radiosity probe along each axis (a probe per 4x4 texels, as in Lumen).
#define LUMINA_RADIOSITY_PROBE_SPACING 4u
// Rays per probe and update: a 4 x 4 stratified hemisphere (uniform in cos(theta) and phi).
#define LUMINA_RADIOSITY_RAYS_PER_SIDE 4u
#define LUMINA_RADIOSITY_RAYS 16u
// Atlas tile side in texels (TileAllocator's kTileSize).
#define LUMINA_ATLAS_TILE_SIZE 16u
#define LUMINA_PROBES_PER_TILE_SIDE 4u
#define LUMINA_PROBES_PER_TILE 16u
// A tile-list pass runs one thread per item (texel or probe) of every listed tile, numbered
// flat and folded into rows of this many threads (AtlasTileList::threadsX, threadsY): no dispatch
// axis passes 65535 groups, even with every tile of a 4096 atlas (16.7 M texels) listed.
#define LUMINA_TILE_LIST_ROW_THREADS 65536u

// Voxel lighting accumulates radiance with 32-bit integer atomics in fixed point: one unit is
// 1 / LUMINA_VOXEL_FIXED_POINT_SCALE of radiance. A texel's weight is its world area over a
// nominal texel's (1 / texelsPerUnit^2), so it adds at most LUMINA_VOXEL_MAX_RADIANCE * scale =
// 2^18 per nominal texel of area, and a voxel face holds 2^14 nominal texels of surface before a
// lane could overflow, whatever its cards' densities (a 64^3 grid over a 4 m room has about 4
// nominal texels per voxel face at 16 texels per metre).
#define LUMINA_VOXEL_FIXED_POINT_SCALE 256.0f
#define LUMINA_VOXEL_MAX_RADIANCE 1024.0f

#ifndef __cplusplus
// Half-float rounding done in float arithmetic on the exact exponent, so that the value written
// to an RGBA16F target is representable and the conversion the write makes is exact, whatever
// its rounding mode (HLSL leaves f32tof16's to the implementation). Measured on lavapipe: the
// radiosity loop passes each value through three half-float layers per bounce (final, voxel
// lighting, indirect), and with raw writes the rho = 0.95 furnace stalled at 19.19, with
// rounded ones at 19.47 (both with the old RGBA8 albedo; docs/surface_cache.md).
// The spacing of half floats around v > 0: 10 fraction bits, denormals below 2^-14.
float halfSpacing(float v) {
    int exponent = max(int((asuint(v) >> 23) & 0xffu) - 127, -14);
    return asfloat(uint(exponent - 10 + 127) << 23);
}
// Nearest half (finite input; non-positive values and NaN become 0: the layers hold light).
float roundToHalf1(float v) {
    return v > 0.0f ? round(v / halfSpacing(v)) * halfSpacing(v) : 0.0f;
}
float4 roundToHalf(float4 v) {
    return float4(roundToHalf1(v.x), roundToHalf1(v.y), roundToHalf1(v.z), roundToHalf1(v.w));
}
// Unbiased (stochastic) rounding to a neighbouring half: up with probability equal to the
// fraction of the spacing v lies above the half below it, given u uniform in [0, 1). Nearest
// rounding stalls a slowly converging loop: once a bounce adds less than half a spacing the sum
// stops growing, a shortfall of (spacing / 2) / (1 - rho), 3 % at rho = 0.99 (docs/gi.md). With
// a fresh u every update the expected value is v, so the loop converges to the right sum.
float roundToHalfDithered1(float v, float u) {
    return v > 0.0f ? floor(v / halfSpacing(v) + u) * halfSpacing(v) : 0.0f;
}
float4 roundToHalfDithered(float4 v, float u) {
    return float4(roundToHalfDithered1(v.x, u), roundToHalfDithered1(v.y, u), roundToHalfDithered1(v.z, u),
                  roundToHalfDithered1(v.w, u));
}
// A well-mixed 32-bit hash (Wellons' lowbias32).
uint hashUint(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
// A uniform number in [0, 1) per texel (or voxel) and update: the dither of roundToHalfDithered.
float ditherOf(uint3 key, uint update) {
    return float(hashUint(key.x ^ hashUint(key.y ^ hashUint(key.z ^ hashUint(update)))) >> 8) *
           (1.0f / 16777216.0f);
}
// The list entry and the item within its tile (texel or probe, row-major) of thread `id` of a
// tile-list dispatch of `itemsPerTile` items a tile; false past the list's `count` entries.
bool tileListItem(uint2 id, uint count, uint itemsPerTile, out uint entry, out uint item) {
    uint flat = id.x + id.y * LUMINA_TILE_LIST_ROW_THREADS;
    entry = flat / itemsPerTile;
    item = flat % itemsPerTile;
    return entry < count;
}

#endif

LUMINA_GPU_NAMESPACE_BEGIN

// A list of atlas tiles to process (row-major tile indices in a StructuredBuffer<uint>).
struct AtlasTileListConstants {
    uint atlasSize;   // texels per side
    uint tileCount;   // tiles in the list
    uint tilesPerRow; // tiles per atlas row
    uint updateIndex; // combine: the dither of its half rounding
};
LUMINA_STATIC_ASSERT_SIZE(AtlasTileListConstants, 16);

struct SurfaceDirectLightConstants {
    uint atlasSize;   // texels per side
    uint tileCount;   // tiles in the list
    uint tilesPerRow; // tiles per atlas row
    uint lightCount;
};
LUMINA_STATIC_ASSERT_SIZE(SurfaceDirectLightConstants, 16);

// Voxel lighting keeps one radiance per voxel and axis-aligned face direction (+x, -x, +y, -y,
// +z, -z: face f holds the light of surfaces whose normal points along it), side by side along
// the texture's x: face f of voxel (x, y, z) is texel (f * dims.x + x, y, z). Without faces, the
// two sides of a wall thinner than a voxel share one radiance, and the sunlit roof of a closed
// room lights its inside (open_top_box was 5.5x too bright).
#define LUMINA_VOXEL_FACES 6u

// The voxel-lighting grid over the scene bounds.
struct VoxelGridInfo {
    float3 boxMin;   // world corner of voxel (0,0,0)
    float voxelSize; // world side of a voxel
    uint3 dims;      // voxels per axis
    uint dimsPadding;
};
LUMINA_STATIC_ASSERT_SIZE(VoxelGridInfo, 32);
LUMINA_STATIC_ASSERT_OFFSET(VoxelGridInfo, voxelSize, 12);
LUMINA_STATIC_ASSERT_OFFSET(VoxelGridInfo, dims, 16);

struct VoxelInjectConstants {
    VoxelGridInfo grid;
    uint atlasSize;         // texels per side
    uint tileCount;         // tiles in the list
    uint tilesPerRow;       // tiles per atlas row
    uint updateIndex;       // the dither of resolve's half rounding
    float nominalTexelArea; // world area of a texel at the cache's full density (1 / texelsPerUnit^2)
    float injectPadding0;
    float injectPadding1;
    float injectPadding2;
};
LUMINA_STATIC_ASSERT_SIZE(VoxelInjectConstants, 64);
LUMINA_STATIC_ASSERT_OFFSET(VoxelInjectConstants, atlasSize, 32);
LUMINA_STATIC_ASSERT_OFFSET(VoxelInjectConstants, nominalTexelArea, 48);

struct RadiosityConstants {
    VoxelGridInfo grid;
    uint atlasSize;        // texels per side
    uint tileCount;        // tiles in the list
    uint tilesPerRow;      // tiles per atlas row
    uint updateIndex;      // the rays' pattern: the tiles' updates since radiosity last restarted
    float originOffset;    // ray origin offset along the normal (world, x the cascade scale where it is)
    float maxDistance;     // of a ray (world)
    float filterMinCosine; // the spatial filter skips neighbours whose normals differ more
    float temporalBlend;   // weight of this update's radiance in the probe history
};
LUMINA_STATIC_ASSERT_SIZE(RadiosityConstants, 64);
LUMINA_STATIC_ASSERT_OFFSET(RadiosityConstants, atlasSize, 32);
LUMINA_STATIC_ASSERT_OFFSET(RadiosityConstants, originOffset, 48);

// A radiosity probe: L1 spherical harmonics of its incoming radiance, one float4 per colour
// channel, (L00, L1 along x, y, z) of the real SH basis, and its surface normal. A probe on no
// surface is all zero (normalAndTexel.w = 0).
struct RadiosityProbe {
    float4 r;
    float4 g;
    float4 b;
    float4 normalAndTexel; // xyz: unit world normal of the probe's texel; w: 0 where no surface, else 1 + the
                           // texel's slot (probeSlotTexel in radiosity.hlsl: its block's or a neighbour's)
};
LUMINA_STATIC_ASSERT_SIZE(RadiosityProbe, 64);

// What the radiosity trace's rays found, summed over every update since the probes were cleared
// (RadiosityPass::readRayStats): the loss of a furnace is the share of hits that read nothing.
// The trace adds to the fields as uints at these indices.
#define LUMINA_RADIOSITY_STAT_RAYS 0u
#define LUMINA_RADIOSITY_STAT_LEFT_SCENE 1u
#define LUMINA_RADIOSITY_STAT_OUT_OF_STEPS 2u
#define LUMINA_RADIOSITY_STAT_HITS 3u
#define LUMINA_RADIOSITY_STAT_GRADIENT_SIDE 4u
#define LUMINA_RADIOSITY_STAT_UNLIT_HITS 5u
#define LUMINA_RADIOSITY_STAT_COUNT 6u
struct RadiosityRayStats {
    uint rays;
    uint leftScene;    // read the sky
    uint outOfSteps;   // still inside after the step budget: read zero
    uint hits;         // read the voxel lighting
    uint gradientSide; // hits whose turned normal found no surface, answered by the SDF gradient's side
    uint unlitHits;    // hits that found no surface either way: read zero
    uint padding0;
    uint padding1;
};
LUMINA_STATIC_ASSERT_SIZE(RadiosityRayStats, 32);

LUMINA_GPU_NAMESPACE_END

#endif
