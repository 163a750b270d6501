#ifndef LUMINA_SH_GRID_SHARED_H
#define LUMINA_SH_GRID_SHARED_H
// The L2 spherical-harmonic probe grid (docs/sh_grid.md), shared by C++ (gi/sh_grid/, tests) and
// HLSL (shaders/sh_grid/).
//
// Probe (x, y, z) of the grid has index x + counts.x * (y + counts.y * z) and sits at
// origin + spacing * (x, y, z). Its nine irradiance coefficients are float4s (rgb; a unused) at
// LUMINA_SH_GRID_COEFFICIENTS * index + k of the probe buffer, k in the order of shBasis. They
// hold the irradiance E_lm = A_l L_lm (the radiance's projection L_lm convolved with the
// clamped cosine, A_l of shCosineBand), so that E(n) = sum_k E_k Y_k(n).
#include "../common/shared_types.h"
#include "../screen_probes/sh_shared.h" // shBasis (the order of k), shCosineBand (A_l)

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_SH_GRID_COEFFICIENTS LUMINA_SH_COEFFICIENTS
#define LUMINA_SH_GRID_FACES 6u
// Threads of the per-face projection (one group per face) and of the per-pixel sampling.
// 256 projection threads: each face runs as one group (on one SM), so the group is made wide; its
// reduction buffer, 256 x 9 float3, stays under D3D's 32 KiB of groupshared memory.
#define LUMINA_SH_GRID_PROJECT_GROUP 256u
#define LUMINA_SH_GRID_SAMPLE_GROUP LUMINA_SCREEN_GROUP_SIZE

// What the sampling pass and the bake's bounce read of the grid (register b0).
struct ShGridConstants {
    float3 origin;     // world position of probe (0, 0, 0)
    uint probeCount;   // counts.x * counts.y * counts.z
    float3 spacing;    // world distance between neighbouring probes along each axis
    float windowBand1; // factor on the l = 1 coefficients when evaluating (1: no windowing)
    uint3 counts;      // probes along x, y, z (each at least 2)
    float windowBand2; // factor on the l = 2 coefficients
    uint width;        // of the sampled image
    uint height;
    uint pad0;
    uint pad1;
};
LUMINA_STATIC_ASSERT_SIZE(ShGridConstants, 64);

// Push constants of the projection of one cube face of one probe (sh_grid_project_face.hlsl).
// The face's camera: the direction through face position (u, v) in [-1, 1]^2 (u right, v up) is
// forward + u right + v up (90-degree field of view, square face, row 0 at the top).
struct ShGridFaceConstants {
    float4 forward; // xyz: unit axis through the face's centre
    float4 right;   // xyz
    float4 up;      // xyz
    uint face;      // 0..5: the slot of the partial sums it writes
    uint faceSize;  // texels per side
    uint bounce;    // 1: surfaces seen also send albedo / pi x the grid's irradiance (a bounce)
    uint pad;
};
LUMINA_STATIC_ASSERT_SIZE(ShGridFaceConstants, 64);

// Push constants of the combination of a probe's six faces (sh_grid_combine.hlsl).
struct ShGridCombineConstants {
    uint probe; // the probe whose coefficients it writes
    uint pad0;
    uint pad1;
    uint pad2;
};
LUMINA_STATIC_ASSERT_SIZE(ShGridCombineConstants, 16);

// The band l of coefficient `index`.
LUMINA_INLINE uint shBand(uint index) {
    return index == 0u ? 0u : (index < 4u ? 1u : 2u);
}

// The solid angle of the part [0, a] x [0, b] of a cube face at distance 1 (signed by a b).
LUMINA_INLINE float shCubeAreaElement(float a, float b) {
    return atan2(a * b, sqrt(a * a + b * b + 1.0f));
}

// The solid angle texel (x, y) (whole numbers) of a face `size` texels across covers.
LUMINA_INLINE float shCubeTexelSolidAngle(float x, float y, float size) {
    const float step = 2.0f / size;
    const float u0 = -1.0f + step * x;
    const float v0 = -1.0f + step * y;
    const float u1 = u0 + step;
    const float v1 = v0 + step;
    return shCubeAreaElement(u1, v1) - shCubeAreaElement(u0, v1) - shCubeAreaElement(u1, v0) +
           shCubeAreaElement(u0, v0);
}

LUMINA_GPU_NAMESPACE_END

#endif
