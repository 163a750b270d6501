#ifndef LUMINA_SP_OCTAHEDRAL_SHARED_H
#define LUMINA_SP_OCTAHEDRAL_SHARED_H
// Octahedral maps of the screen probes, shared by C++ (tests) and HLSL.
//
// Two maps, both addressed by e in [-1, 1]^2:
//   - hemi-octahedral (radiance, one 8x8 map per probe in the probe's tangent frame, +z the
//     probe normal): the whole square covers the hemisphere, so no texel straddles the horizon
//     and no ray is spent below the surface;
//   - full octahedral (irradiance, world space): the whole sphere, stored with a one-texel
//     border so that hardware bilinear filtering never reads another probe's tile.
//
// Solid angle: a point e of either map lies on the octahedron |x| + |y| + |z| = 1 at p before
// normalisation; d(omega) = dA_face * cos / |p|^2 = de / |p|^3 for the full map (its fold is
// area preserving), and half that for the hemi map (its 45-degree turn halves the area).
#include "../common/shared_types.h"
#include "../common/constants_shared.h"
#include "sh_shared.h"

#ifdef __cplusplus
namespace lumina::gpu {
using glm::normalize;
inline float sp_floor(float x) {
    return std::floor(x);
}
} // namespace lumina::gpu
#define LUMINA_SP_FLOOR sp_floor
#else
#define LUMINA_SP_FLOOR floor
#endif

LUMINA_GPU_NAMESPACE_BEGIN

// Edge of a probe's hemi-octahedral radiance map: 64 texels, one per ray at the default 64 rays
// (the thesis's 8 x 8).
#define LUMINA_SP_OCT_SIZE 8u

LUMINA_INLINE float spSignNotZero(float x) {
    return x >= 0.0f ? 1.0f : -1.0f;
}

// --- hemi-octahedral: unit direction with z >= 0 <-> e in [-1, 1]^2 ---------------------------
LUMINA_INLINE float2 hemiOctEncode(float3 d) {
    const float s = abs(d.x) + abs(d.y) + max(d.z, 0.0f);
    const float px = d.x / s;
    const float py = d.y / s;
    return float2(px + py, px - py);
}

// The point on the octahedron face (not normalised).
LUMINA_INLINE float3 hemiOctPoint(float2 e) {
    const float px = 0.5f * (e.x + e.y);
    const float py = 0.5f * (e.x - e.y);
    return float3(px, py, 1.0f - abs(px) - abs(py));
}

LUMINA_INLINE float3 hemiOctDecode(float2 e) {
    return normalize(hemiOctPoint(e));
}

// d(omega) / d(e): solid angle per unit area of e.
LUMINA_INLINE float hemiOctJacobian(float2 e) {
    const float3 p = hemiOctPoint(e);
    const float len = sqrt(dot(p, p));
    return 0.5f / (len * len * len);
}

// --- full octahedral: any unit direction <-> e in [-1, 1]^2 -------------------------------------
LUMINA_INLINE float2 octEncode(float3 d) {
    const float s = abs(d.x) + abs(d.y) + abs(d.z);
    float px = d.x / s;
    float py = d.y / s;
    if (d.z < 0.0f) {
        const float fx = (1.0f - abs(py)) * spSignNotZero(px);
        const float fy = (1.0f - abs(px)) * spSignNotZero(py);
        px = fx;
        py = fy;
    }
    return float2(px, py);
}

LUMINA_INLINE float3 octPoint(float2 e) {
    float3 p = float3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    if (p.z < 0.0f) {
        const float fx = (1.0f - abs(e.y)) * spSignNotZero(e.x);
        const float fy = (1.0f - abs(e.x)) * spSignNotZero(e.y);
        p.x = fx;
        p.y = fy;
    }
    return p;
}

LUMINA_INLINE float3 octDecode(float2 e) {
    return normalize(octPoint(e));
}

LUMINA_INLINE float octJacobian(float2 e) {
    const float3 p = octPoint(e);
    const float len = sqrt(dot(p, p));
    return 1.0f / (len * len * len);
}

// --- texels ---------------------------------------------------------------------------------------
// Texel (x, y) of an n x n map covers e in [-1 + 2x/n, -1 + 2(x+1)/n] (y likewise).
LUMINA_INLINE float2 octTexelCentre(uint x, uint y, uint n) {
    return float2((float(x) + 0.5f) * 2.0f / float(n) - 1.0f, (float(y) + 0.5f) * 2.0f / float(n) - 1.0f);
}

LUMINA_INLINE uint octTexelOf(float2 e, uint n) {
    const float last = float(n) - 1.0f;
    const float x = min(max(LUMINA_SP_FLOOR((e.x * 0.5f + 0.5f) * float(n)), 0.0f), last);
    const float y = min(max(LUMINA_SP_FLOOR((e.y * 0.5f + 0.5f) * float(n)), 0.0f), last);
    return uint(y) * n + uint(x);
}

// Integrals over a texel use a 4 x 4 midpoint grid (solid angles exact to about 1e-4 relative at
// n = 8; the unit test checks their sum, 2 pi). Sample q (0 .. 15) of texel (x, y) of an n x n map:
#define LUMINA_SP_TEXEL_QUADRATURE 4u
#define LUMINA_SP_TEXEL_SAMPLES (LUMINA_SP_TEXEL_QUADRATURE * LUMINA_SP_TEXEL_QUADRATURE)
LUMINA_INLINE float2 octTexelSample(uint x, uint y, uint n, uint q) {
    const float size = 2.0f / float(n);
    const float step = size / float(LUMINA_SP_TEXEL_QUADRATURE);
    return float2(-1.0f + size * float(x) + step * (float(q % LUMINA_SP_TEXEL_QUADRATURE) + 0.5f),
                  -1.0f + size * float(y) + step * (float(q / LUMINA_SP_TEXEL_QUADRATURE) + 0.5f));
}

// Area in e of one quadrature sample.
LUMINA_INLINE float octTexelSampleArea(uint n) {
    const float step = 2.0f / float(n * LUMINA_SP_TEXEL_QUADRATURE);
    return step * step;
}

// Solid angle of texel (x, y) of an n x n hemi-octahedral map. Unrolled: as a loop, vkd3d-shader
// 2.1's DXBC of it computed other values on Wine's D3D12 (every texel's solid angle, so the probe
// composite's weights, came out wrong; docs/d3d12.md); unrolled it matches Vulkan, and the SPIR-V
// computes the same bits either way.
LUMINA_INLINE float hemiOctTexelSolidAngle(uint x, uint y, uint n) {
    float sum = 0.0f;
    LUMINA_UNROLL for (uint q = 0u; q < LUMINA_SP_TEXEL_SAMPLES; ++q) {
        sum += hemiOctJacobian(octTexelSample(x, y, n, q));
    }
    return sum * octTexelSampleArea(n);
}

// A texel of a bordered tile ((n + 2)^2, interior texel (x, y) at (x + 1, y + 1)) to the map
// position it shows. Border texels repeat the interior across the octahedral seams: the square's
// edges are mirrored about their midpoints, so e = (1 + t, y) is the direction of (1 - t, -y), and
// each corner shows the opposite corner. Filtering at an interior edge then blends the texels
// that are neighbours on the sphere.
LUMINA_INLINE float2 octBorderedTexelPosition(uint tx, uint ty, uint n) {
    float ex = (float(tx) - 0.5f) * 2.0f / float(n) - 1.0f;
    float ey = (float(ty) - 0.5f) * 2.0f / float(n) - 1.0f;
    if (abs(ex) > 1.0f) {
        ex = spSignNotZero(ex) * (2.0f - abs(ex));
        ey = -ey;
    }
    if (abs(ey) > 1.0f) {
        ey = spSignNotZero(ey) * (2.0f - abs(ey));
        ex = -ex;
    }
    return float2(ex, ey);
}

// --- the probe's tangent frame -----------------------------------------------------------------------
// Branchless orthonormal basis (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1),
// 2017): a frame that depends on the normal alone, so that every pass (and the previous frame)
// agrees on where each texel of a probe's map points.
struct ProbeFrame {
    float3 tangent;
    float3 bitangent;
    float3 normal;
};

LUMINA_INLINE ProbeFrame probeFrame(float3 n) {
    const float s = spSignNotZero(n.z);
    const float a = -1.0f / (s + n.z);
    const float b = n.x * n.y * a;
    ProbeFrame f;
    f.tangent = float3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    f.bitangent = float3(b, s + n.y * n.y * a, -n.y);
    f.normal = n;
    return f;
}

LUMINA_INLINE float3 probeToWorld(ProbeFrame f, float3 local) {
    return f.tangent * local.x + f.bitangent * local.y + f.normal * local.z;
}

LUMINA_INLINE float3 worldToProbe(ProbeFrame f, float3 d) {
    return float3(dot(d, f.tangent), dot(d, f.bitangent), dot(d, f.normal));
}

// The integrals of the nine SH basis functions (in world space) over texel (x, y) of an n x n
// hemi-octahedral map in frame f: projecting a map onto SH is the sum over texels of their
// radiance times these. Same 4 x 4 quadrature as the solid angle.
LUMINA_INLINE Sh9 hemiOctTexelShIntegrals(uint x, uint y, uint n, ProbeFrame f) {
    Sh9 result;
    for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
        result.v[k] = 0.0f;
    }
    for (uint q = 0u; q < LUMINA_SP_TEXEL_SAMPLES; ++q) {
        const float2 e = octTexelSample(x, y, n, q);
        const float w = hemiOctJacobian(e) * octTexelSampleArea(n);
        const float3 d = probeToWorld(f, hemiOctDecode(e));
        for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
            result.v[k] += w * shBasis(k, d);
        }
    }
    return result;
}

LUMINA_GPU_NAMESPACE_END

#endif
