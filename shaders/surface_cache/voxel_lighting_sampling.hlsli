#ifndef LUMINA_VOXEL_LIGHTING_SAMPLING_HLSLI
#define LUMINA_VOXEL_LIGHTING_SAMPLING_HLSLI
// Radiance of the voxel lighting (voxel_lighting.hlsl) at an SDF hit p of unit normal n: of
// each face n points along (LUMINA_VOXEL_FACES), weighted by the squared normal component, a
// trilinear lookup over the eight voxels around p - n * half a voxel, each weighted by its
// coverage (a), so the empty voxels in front of the surface do not darken it. The face keeps
// the two sides of a thin wall apart: a ray from inside a room reads the inside. The lean along
// -n is the normal weighting: an SDF hit lies in front of its surface (the tracer stops short,
// and the zero crossing of a coarse mesh SDF sits up to about half a mesh voxel off the
// triangles), so the voxels holding the surface's texels are behind p, never in front. Where
// that finds no covered voxel, a second lookup one voxel further back (a hit stopped far short).
// Zero where neither finds a surface. `ray` is the direction of the ray that found the hit, or
// zero: a face that faces along the ray is one the ray cannot see, and is skipped. A cone that
// passes a sheet's edge (sunlit_rooms: through the ceiling opening, past its rim) stops with a
// normal pointing away from the edge, whose small component across the sheet named its sunlit
// top for a ray going up, and the coverage weighting made that face the whole answer.
//
//   Texture3D<float4> gVoxelLighting;    // the includer binds it
//   #define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/surface_cache_lighting_shared.h"

#if !defined(LUMINA_VOXEL_LIGHTING)
#error "define LUMINA_VOXEL_LIGHTING before including voxel_lighting_sampling.hlsli"
#endif

// Coverage-weighted trilinear lookup at p in the faces n points along that `ray` can see: rgb,
// and the summed weight in a.
float4 voxelLightingTrilinear(VoxelGridInfo grid, float3 p, float3 n, float3 ray) {
    float voxel = grid.voxelSize;
    float3 local = (p - grid.boxMin) / voxel - 0.5f;
    int3 base = int3(floor(local));
    float3 f = local - float3(base);
    int3 last = int3(grid.dims) - 1;
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float weight = 0.0f;
    for (uint axis = 0u; axis < 3u; ++axis) {
        // The normal's component by selection, not n[axis], and the corner's weights by selection,
        // not from a cast of its offset: vkd3d-shader miscompiled this function's DXBC otherwise
        // (docs/d3d12.md).
        float na = axis == 0u ? n.x : (axis == 1u ? n.y : n.z);
        float ra = axis == 0u ? ray.x : (axis == 1u ? ray.y : ray.z);
        float faceWeight = na * ra > 0.0f ? 0.0f : na * na;
        if (faceWeight <= 0.0f) {
            continue;
        }
        int faceColumn = int(2u * axis + (na < 0.0f ? 1u : 0u)) * int(grid.dims.x);
        for (uint corner = 0u; corner < 8u; ++corner) {
            bool3 high = bool3((corner & 1u) != 0u, (corner & 2u) != 0u, (corner & 4u) != 0u);
            int3 v = base + int3(high.x ? 1 : 0, high.y ? 1 : 0, high.z ? 1 : 0);
            if (any(v < 0) || any(v > last)) {
                continue;
            }
            float3 w3 = float3(high.x ? f.x : 1.0f - f.x, high.y ? f.y : 1.0f - f.y, high.z ? f.z : 1.0f - f.z);
            float4 texel = LUMINA_VOXEL_LIGHTING.Load(int4(v.x + faceColumn, v.y, v.z, 0));
            float w = faceWeight * w3.x * w3.y * w3.z * texel.a;
            sum += w * texel.rgb;
            weight += w;
        }
    }
    return float4(weight > 0.0f ? sum / weight : float3(0.0f, 0.0f, 0.0f), weight);
}

// The lookup half a voxel behind p, or one and a half where that finds nothing: rgb, and the
// weight of the one that answered in a (zero: no surface found).
float4 voxelLightingBehind(VoxelGridInfo grid, float3 p, float3 n, float3 ray) {
    float voxel = grid.voxelSize;
    float4 near = voxelLightingTrilinear(grid, p - 0.5f * voxel * n, n, ray);
    if (near.a > 0.0f) {
        return near;
    }
    return voxelLightingTrilinear(grid, p - 1.5f * voxel * n, n, ray);
}

float3 sampleVoxelLighting(VoxelGridInfo grid, float3 p, float3 n, float3 ray) {
    return voxelLightingBehind(grid, p, n, ray).rgb;
}

// The lookup of a hit whose normal n was turned to face the ray (sdfFacingNormal) from the SDF
// gradient g: where the turned normal finds no surface, g's own side, still without the faces
// the ray cannot see. Turning is right for a ray that crossed an open surface's plane, but a ray
// that grazes past a solid's convex edge stops with a gradient pointing away from the edge, partly
// along the ray: turned, its lean goes into empty space and found nothing, and at rho = 0.99 these
// zero reads (0.02 % of the furnace's rays) cost 2 % of the radiance (docs/gi.md, energy). The
// fallback reads only faces that face the ray, so it cannot read a thin wall's far side.
// a: the answering lookup's weight, negated where g's side answered (zero: nothing found).
float4 voxelLightingSeenSide(VoxelGridInfo grid, float3 p, float3 n, float3 g, float3 ray) {
    float4 turned = voxelLightingBehind(grid, p, n, ray);
    if (turned.a > 0.0f || !(dot(n, g) < 0.0f)) {
        return turned;
    }
    float4 gradientSide = voxelLightingBehind(grid, p, g, ray);
    return float4(gradientSide.rgb, -gradientSide.a);
}

#endif
