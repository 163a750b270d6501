#ifndef LUMINA_SP_SH_SHARED_H
#define LUMINA_SP_SH_SHARED_H
// Real spherical harmonics up to L2 (9 coefficients) and irradiance from them, shared by C++
// (tests) and HLSL (probe_sh_irradiance.hlsl).
//
// Basis: the usual real SH (Sloan, "Stupid Spherical Harmonics Tricks", 2008), index
// l * (l + 1) + m. Irradiance (Ramamoorthi and Hanrahan, "An Efficient Representation for
// Irradiance Environment Maps", 2001): E(n) = sum_lm A_l L_lm Y_lm(n), with the clamped cosine's
// zonal factors A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4. Truncating at L2 rings: a cosine lobe of
// radiance gives slightly negative irradiance on its far side, which shIrradiance clamps to 0
// (docs/architecture.md, "Numerical hygiene": SH reconstruction clamps negatives).
#include "../common/shared_types.h"
#include "../common/constants_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_SH_COEFFICIENTS 9u
// Integral of Y_00 over the sphere, 4 pi x 0.2820948 = 2 sqrt(pi): a constant radiance M projects
// to M times this in coefficient 0 and to 0 elsewhere.
#define LUMINA_SH_SPHERE_INTEGRAL_0 3.544907702f

LUMINA_INLINE float shBasis(uint index, float3 d) {
    switch (index) {
    case 0u:
        return LUMINA_SH_Y00;
    case 1u:
        return LUMINA_SH_Y1 * d.y;
    case 2u:
        return LUMINA_SH_Y1 * d.z;
    case 3u:
        return LUMINA_SH_Y1 * d.x;
    case 4u:
        return LUMINA_SH_Y2_XY * d.x * d.y;
    case 5u:
        return LUMINA_SH_Y2_XY * d.y * d.z;
    case 6u:
        return LUMINA_SH_Y20 * (3.0f * d.z * d.z - 1.0f);
    case 7u:
        return LUMINA_SH_Y2_XY * d.x * d.z;
    default:
        return LUMINA_SH_Y22 * (d.x * d.x - d.y * d.y);
    }
}

// A_l of the clamped cosine for the band of coefficient `index`.
LUMINA_INLINE float shCosineBand(uint index) {
    return index == 0u ? LUMINA_SH_COSINE_A0 : (index < 4u ? LUMINA_SH_COSINE_A1 : LUMINA_SH_COSINE_A2);
}

// Nine coefficients of one scalar function.
struct Sh9 {
    float v[9];
};

// Irradiance from the L2 radiance coefficients of each colour channel, clamped at 0.
LUMINA_INLINE float3 shIrradiance(Sh9 r, Sh9 g, Sh9 b, float3 n) {
    float3 e = float3(0.0f, 0.0f, 0.0f);
    for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
        const float y = shBasis(k, n) * shCosineBand(k);
        e.x += r.v[k] * y;
        e.y += g.v[k] * y;
        e.z += b.v[k] * y;
    }
    return max(e, float3(0.0f, 0.0f, 0.0f));
}

LUMINA_GPU_NAMESPACE_END

#endif
