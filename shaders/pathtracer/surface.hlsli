#ifndef LUMINA_PT_SURFACE_HLSLI
#define LUMINA_PT_SURFACE_HLSLI
// The surface a ray hit: position, normals, texture coordinates and material, read from the
// BVH's world-space triangle and the GpuScene buffers (object-space vertices placed by their
// instance). The includer declares gBvhTriangles, gTriangles, gVertices, gIndices and
// gInstances (path_trace.hlsl).
#include "common/bvh_shared.h"
#include "common/scene_shared.h"
#include "pathtracer/pathtracer_shared.h"

struct PtSurface {
    float3 position;
    float3 frontNormal;   // unit geometric normal of the front face (counter-clockwise in object space)
    float3 shadingNormal; // unit interpolated vertex normal, on the front normal's side
    float2 uv;
    uint material;
    uint emitter; // LUMINA_PT_NOT_EMISSIVE when the triangle emits nothing
};

float3 ptRowTransform(float4 rows[3], float3 v) {
    return float3(dot(rows[0].xyz, v), dot(rows[1].xyz, v), dot(rows[2].xyz, v));
}

// Front-face geometric normal of a world-space triangle (not normalised).
float3 ptFrontNormal(float3 v0, float3 v1, float3 v2, uint triangleFlags) {
    float3 n = cross(v1 - v0, v2 - v0);
    return (triangleFlags & LUMINA_PT_TRIANGLE_MIRRORED) != 0u ? -n : n;
}

// Interpolated object-space attributes of a traced triangle: xyz normal, then uv.
void ptInterpolateAttributes(PtTriangle tri, float2 bary, out float3 worldNormal, out float2 uv) {
    float w0 = 1.0f - bary.x - bary.y;
    GpuVertex a = gVertices[gIndices[tri.info.y]];
    GpuVertex b = gVertices[gIndices[tri.info.y + 1u]];
    GpuVertex c = gVertices[gIndices[tri.info.y + 2u]];
    float3 n = a.normalV.xyz * w0 + b.normalV.xyz * bary.x + c.normalV.xyz * bary.y;
    uv = float2(a.positionU.w, a.normalV.w) * w0 + float2(b.positionU.w, b.normalV.w) * bary.x +
         float2(c.positionU.w, c.normalV.w) * bary.y;
    GpuInstance instance = gInstances[tri.info.x];
    worldNormal = ptRowTransform(instance.normalToWorld, n);
}

PtSurface ptLoadSurface(uint bvhTriangle, uint triangleIndex, float2 bary) {
    BvhTriangle bt = gBvhTriangles[bvhTriangle];
    PtTriangle tri = gTriangles[triangleIndex];
    PtSurface s;
    float w0 = 1.0f - bary.x - bary.y;
    s.position = bt.v0.xyz * w0 + bt.v1.xyz * bary.x + bt.v2.xyz * bary.y;
    s.frontNormal = normalize(ptFrontNormal(bt.v0.xyz, bt.v1.xyz, bt.v2.xyz, tri.info.z));
    float3 n;
    ptInterpolateAttributes(tri, bary, n, s.uv);
    float len2 = dot(n, n);
    n = len2 > 0.0f ? n * rsqrt(len2) : s.frontNormal;
    // Normals that disagree with the winding are taken to the front side.
    s.shadingNormal = dot(n, s.frontNormal) < 0.0f ? -n : n;
    s.material = tri.info.z >> 8u;
    s.emitter = tri.info.w;
    return s;
}

#endif
