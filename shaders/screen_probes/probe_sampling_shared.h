#ifndef LUMINA_SP_PROBE_SAMPLING_SHARED_H
#define LUMINA_SP_PROBE_SAMPLING_SHARED_H
// Ray directions of the screen probes, shared by C++ (tests) and HLSL (probe_ray_generation.hlsl).
//
// Each probe traces n rays: nBrdf from the BRDF PDF, the rest from the lighting PDF. Both are
// tables over the probe's 8 x 8 hemi-octahedral texels (probability of each texel); a ray picks
// its texel by inverting the table's CDF and a point in it uniformly in e, so its density is
//     p_s(omega) = P_s[texel] / (texelArea * J(e)),  J = hemiOctJacobian, texelArea = (2 / 8)^2.
// The balance heuristic over both strategies (Veach 1997, multi-sample model) gives every ray the
// weight 1 / (nBrdf p_b(omega) + nLight p_l(omega)): an estimate of the integral of f is the sum
// over all rays of weight * f. Strategy s's own balance weight is n_s p_s / (sum_k n_k p_k).
//
// Low discrepancy: strategy-local index i of n_s rays takes the Hammersley point
// ((i + 0.5) / n_s, radicalInverse(i)), rotated per frame by the R2 sequence (Roberts 2018) and per
// probe by a hash (Cranley-Patterson rotation): stratified within a frame, different every frame,
// and decorrelated between neighbouring probes so that the spatial filter averages distinct rays.
#include "octahedral_shared.h"

#ifdef __cplusplus
namespace lumina::gpu {
inline float sp_frac(float x) {
    return x - std::floor(x);
}
} // namespace lumina::gpu
#define LUMINA_SP_FRAC sp_frac
#define LUMINA_SP_REVERSEBITS luminaReverseBits // shared_types.h
#else
#define LUMINA_SP_FRAC frac
#define LUMINA_SP_REVERSEBITS reversebits
#endif

LUMINA_GPU_NAMESPACE_BEGIN

// The R2 sequence's plastic-number constants 1 / phi2 and 1 / phi2^2 in 32-bit fixed point
// (x 2^32): frame x constant then wraps exactly modulo 1, so the rotation keeps its 24 bits of
// precision however many frames have run (float(frame) x 0.75 would lose them past 2^16 frames).
#define LUMINA_SP_R2_A1_FIXED 3242174889u
#define LUMINA_SP_R2_A2_FIXED 2447445414u
// 2^-24: the top 24 bits of a 32-bit fraction to [0, 1) exactly.
#define LUMINA_SP_UINT24_TO_UNIT 5.9604644775390625e-8f
// 2^-32 as a float: a 32-bit radical inverse to [0, 1).
#define LUMINA_SP_UINT32_TO_UNIT 2.3283064365386963e-10f

LUMINA_INLINE uint spHash(uint value) { // PCG output permutation (Jarzynski and Olano 2020)
    const uint state = value * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

LUMINA_INLINE float2 spHammersley(uint i, uint n) {
    return float2((float(i) + 0.5f) / float(n), float(LUMINA_SP_REVERSEBITS(i)) * LUMINA_SP_UINT32_TO_UNIT);
}

// The rotation of frame `frame` for probe `probe` and strategy `strategy`.
LUMINA_INLINE float2 spRotation(uint frame, uint probe, uint strategy) {
    const uint hx = spHash(probe * 2u + strategy);
    const uint hy = spHash(hx);
    const uint x = hx + frame * LUMINA_SP_R2_A1_FIXED; // wraps: a fraction in 32-bit fixed point
    const uint y = hy + frame * LUMINA_SP_R2_A2_FIXED;
    return float2(float(x >> 8u) * LUMINA_SP_UINT24_TO_UNIT, float(y >> 8u) * LUMINA_SP_UINT24_TO_UNIT);
}

LUMINA_INLINE float2 spSamplePoint(uint i, uint n, uint frame, uint probe, uint strategy) {
    const float2 h = spHammersley(i, n);
    const float2 r = spRotation(frame, probe, strategy);
    // min: frac of a sum can round to 1.0 in float.
    return float2(min(LUMINA_SP_FRAC(h.x + r.x), 0.99999994f), min(LUMINA_SP_FRAC(h.y + r.y), 0.99999994f));
}

// The number that seeds a probe's directions (spSamplePoint's `probe`): a uniform probe's slot; an
// adaptive probe's slot (from uniformCount on) depends on how many tiles above it wanted one
// (probe_adaptive_allocation.hlsl), so its pixel seeds it instead, numbered past every uniform slot:
// a probe elsewhere that appears or goes does not change its rays.
LUMINA_INLINE uint spProbeSeed(uint slot, uint uniformCount, uint2 pixel, uint imageWidth) {
    return slot < uniformCount ? slot : uniformCount + pixel.y * imageWidth + pixel.x;
}

// The luminance the lighting PDF weighs a texel by (probe_lighting_pdf.hlsl), cut to 4 mantissa
// bits: within 1/16 of itself. The APIs round last frame's radiance differently by an ULP here and
// there; on the full value that moved a texel's probability, the same random numbers drew other
// rays, and after 8 frames D3D12's rays in the emissive Cornell box parted from Vulkan's by up to
// 0.27 (99th percentile). Cut, an ULP almost never changes the table (0.00024). A PDF only steers
// samples: the estimate stays unbiased (docs/gi.md, energy 20.).
LUMINA_INLINE float spLightingPdfLuminance(float luminance) {
    return asfloat(asuint(luminance) & 0xFFF80000u);
}

// Area of one texel of an n x n map in e units.
LUMINA_INLINE float spTexelArea(uint n) {
    const float size = 2.0f / float(n);
    return size * size;
}

// Density in solid angle of a table strategy with texel probability `p` at map position e.
LUMINA_INLINE float spTableDensity(float p, float2 e, uint n) {
    return p / (spTexelArea(n) * hemiOctJacobian(e));
}

// The multi-sample balance-heuristic weight of a ray (see above); 0 where neither strategy can
// produce it.
LUMINA_INLINE float spMisWeight(float nBrdf, float pBrdf, float nLight, float pLight) {
    // A strategy that draws no rays is left out, table and all (its pass may not have run).
    const float sum = (nBrdf > 0.0f ? nBrdf * pBrdf : 0.0f) + (nLight > 0.0f ? nLight * pLight : 0.0f);
    return sum > 0.0f ? 1.0f / sum : 0.0f;
}

// Strategy s's balance-heuristic share at a direction: n_s p_s / sum_k n_k p_k (the shares sum to 1).
LUMINA_INLINE float spBalanceShare(float nS, float pS, float nOther, float pOther) {
    const float sum = nS * pS + nOther * pOther;
    return sum > 0.0f ? nS * pS / sum : 0.0f;
}

// The probabilities of the 64 texels of a probe's radiance map, four per float4.
#define LUMINA_SP_TABLE_SIZE (LUMINA_SP_OCT_SIZE * LUMINA_SP_OCT_SIZE)
struct SpTexelTable {
    float4 p[16];
};

LUMINA_INLINE float spTableAt(SpTexelTable t, uint i) {
    return t.p[i >> 2u][i & 3u];
}

// Probability mass of texel (x, y) of an n x n hemi-octahedral map under the cosine-weighted
// hemisphere (pdf cos / pi): the same 4 x 4 quadrature as hemiOctTexelSolidAngle, unrolled for the
// same reason.
LUMINA_INLINE float hemiOctTexelCosineMass(uint x, uint y, uint n) {
    float sum = 0.0f;
    LUMINA_UNROLL for (uint q = 0u; q < LUMINA_SP_TEXEL_SAMPLES; ++q) {
        const float2 e = octTexelSample(x, y, n, q);
        sum += hemiOctJacobian(e) * hemiOctDecode(e).z;
    }
    return sum * octTexelSampleArea(n) * (1.0f / LUMINA_PI);
}

struct SpTableSample {
    float2 e;          // map position, [-1, 1]^2
    uint texel;        // y * 8 + x
    float probability; // the texel's table entry
};

// The point u warped into texel k of a table whose CDF before k is `before`: the remainder of u.x
// within the texel's share places the point across the texel (so the stratification of u.x
// carries over), u.y along it.
LUMINA_INLINE SpTableSample spTableSampleAt(uint k, float before, float p, float2 u) {
    const uint n = LUMINA_SP_OCT_SIZE;
    const float across = p > 0.0f ? min(max((u.x - before) / p, 0.0f), 1.0f) : 0.5f;
    const float size = 2.0f / float(n);
    SpTableSample s;
    s.texel = k;
    s.probability = p;
    s.e = float2(-1.0f + size * (float(k % n) + across), -1.0f + size * (float(k / n) + u.y));
    return s;
}

// Inverts the table's CDF with u.x by a linear search (the CPU reference; the kernel searches a
// prefix-sum table in groupshared memory by bisection and finds the same texel: the first whose
// CDF interval holds u.x, never one of probability 0 unless u.x is past the total).
LUMINA_INLINE SpTableSample spSampleTable(SpTexelTable t, float2 u) {
    float before = 0.0f;
    float p = 0.0f;
    uint k = 0u;
    for (uint i = 0u; i < LUMINA_SP_TABLE_SIZE; ++i) {
        p = spTableAt(t, i);
        k = i;
        if (u.x < before + p || i + 1u == LUMINA_SP_TABLE_SIZE) {
            break;
        }
        before += p;
    }
    return spTableSampleAt(k, before, p, u);
}

LUMINA_GPU_NAMESPACE_END

#endif
