#ifndef LUMINA_PATHTRACER_SHARED_H
#define LUMINA_PATHTRACER_SHARED_H
// GPU layout of the reference path tracer (gi/pathtracer/, shaders/pathtracer/), shared by
// C++ and HLSL. Conventions (camera, pixel footprint, units, lights, random numbers,
// accumulation) are written down in docs/conventions.md.
#include "../common/camera_shared.h"
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

// PtTriangle.info.w when a triangle emits nothing.
#define LUMINA_PT_NOT_EMISSIVE 0xFFFFFFFFu
// PtTriangle.info.z flags.
#define LUMINA_PT_TRIANGLE_MIRRORED 1u // its instance mirrors: the front face winds clockwise in world space

// PathTraceConstants.flags.
#define LUMINA_PT_FLAG_JITTER 1u // sample the pixel footprint; off: the pixel centre only
#define LUMINA_PT_FLAG_AOVS 2u   // accumulate albedo, normal, direct and indirect

// One traced triangle; the BVH's primitive id is its index. Vertices, normals and uvs are
// read from the GpuScene buffers (object space) through the instance.
struct PtTriangle {
    uint4 info; // x: instance; y: position of its first index in the scene index buffer;
                // z: flags (LUMINA_PT_TRIANGLE_*) | material << 8; w: emitter index or LUMINA_PT_NOT_EMISSIVE
};

// One emissive triangle, sampled uniformly by area for next-event estimation.
struct PtEmitter {
    float4 v0AndArea;    // xyz: world position of corner 0; w: world area
    float4 edge1AndPdf;  // xyz: v1 - v0; w: probability of choosing this emitter
    float4 edge2AndSign; // xyz: v2 - v0; w: +1 when cross(edge1, edge2) is the front face's normal, else -1
    uint4 info;          // x: triangle (PtTriangle index); yzw: unused
};

// Vose alias table over the emitters: pick i uniformly, keep it with probability
// `probability`, else take `alias`.
struct PtAliasEntry {
    float probability;
    uint alias;
    uint pad0;
    uint pad1;
};

// Running means of the AOVs of one pixel (LUMINA_PT_FLAG_AOVS), over the same samples as the
// radiance. The first hit is the surface the camera ray meets (none: zeros).
struct PtPixelAovs {
    float4 albedo;   // rgb: base colour x texture at the first hit
    float4 normal;   // xyz: shading normal at the first hit, on the camera's side of the surface
    float4 direct;   // rgb: light that reached the camera after at most one bounce
    float4 indirect; // rgb: light that reached the camera after two or more bounces
};

// Constants of one render (constant buffer b0).
struct PathTraceConstants {
    GpuCamera camera;
    uint lightCount;
    uint emitterCount; // emissive triangles
    uint maxBounces;
    uint flags; // LUMINA_PT_FLAG_*
    uint width; // of the image, in pixels
    uint height;
    uint seed;
    uint rouletteStartBounce; // Russian roulette starts after this many bounces
};

// Push constants of one sample pass over one tile.
struct PathTracePassConstants {
    uint sampleIndex; // 0-based; the pixel means become means over sampleIndex + 1 samples
    uint tileX;       // tile origin in pixels
    uint tileY;
    uint pad0;
};

// Push constants of the ray-query kernel (tests: the scene BVH against brute force).
struct PtRayQueryConstants {
    uint rayCount;
    uint pad0;
    uint pad1;
    uint pad2;
};

LUMINA_STATIC_ASSERT_SIZE(PtTriangle, 16);
LUMINA_STATIC_ASSERT_SIZE(PtEmitter, 64);
LUMINA_STATIC_ASSERT_SIZE(PtAliasEntry, 16);
LUMINA_STATIC_ASSERT_SIZE(PtPixelAovs, 64);
LUMINA_STATIC_ASSERT_SIZE(PathTraceConstants, 176);
LUMINA_STATIC_ASSERT_OFFSET(PathTraceConstants, lightCount, 144);
LUMINA_STATIC_ASSERT_OFFSET(PathTraceConstants, width, 160);
LUMINA_STATIC_ASSERT_SIZE(PathTracePassConstants, 16);
LUMINA_STATIC_ASSERT_SIZE(PtRayQueryConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
