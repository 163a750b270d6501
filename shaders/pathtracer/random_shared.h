#ifndef LUMINA_PT_RANDOM_SHARED_H
#define LUMINA_PT_RANDOM_SHARED_H
// Random numbers and sampling of the reference path tracer, shared by C++ (tests) and HLSL.
//
// Every path has its own generator, seeded by hashing (seed, pixel, sample index):
//   state = pcgHash(pixelIndex + pcgHash(sampleIndex + pcgHash(seed)))
// and advanced as the 32-bit PCG LCG (O'Neill 2014) with the RXS-M-XS output permutation
// (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020). A result
// therefore depends only on the seed, the pixel and the sample index: not on the tile
// size, the dispatch order or the number of samples per submission.
#include "../common/shared_types.h"
#include "../common/constants_shared.h"

#ifdef __cplusplus
namespace lumina::gpu {
using std::cos;
using std::sin;
} // namespace lumina::gpu
#endif

LUMINA_GPU_NAMESPACE_BEGIN

// 2^-24: maps the top 24 bits of a 32-bit word to [0, 1) exactly.
#define LUMINA_PT_UINT24_TO_UNIT 5.9604644775390625e-8f

LUMINA_INLINE uint pcgHash(uint value) {
    const uint state = value * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

struct PtRng {
    uint state;
};

LUMINA_INLINE PtRng ptRngCreate(uint seed, uint pixelIndex, uint sampleIndex) {
    PtRng rng;
    rng.state = pcgHash(pixelIndex + pcgHash(sampleIndex + pcgHash(seed)));
    return rng;
}

LUMINA_INLINE uint ptRngNextUint(LUMINA_INOUT(PtRng) rng) {
    const uint state = rng.state;
    rng.state = state * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1): never 1, so floor(u * n) < n.
LUMINA_INLINE float ptRngNext(LUMINA_INOUT(PtRng) rng) {
    return float(ptRngNextUint(rng) >> 8u) * LUMINA_PT_UINT24_TO_UNIT;
}

// Cosine-weighted direction about +z (Malley's method): pdf = cos(theta) / pi.
LUMINA_INLINE float3 ptSampleCosineHemisphere(float u1, float u2) {
    const float r = sqrt(u1);
    const float phi = 2.0f * LUMINA_PI * u2;
    return float3(r * cos(phi), r * sin(phi), sqrt(max(0.0f, 1.0f - u1)));
}

// Barycentric weights (of v1, v2) of a point uniform in a triangle's area (Turk 1990 / pbrt).
LUMINA_INLINE float2 ptSampleTriangle(float u1, float u2) {
    const float s = sqrt(u1);
    return float2(s * (1.0f - u2), s * u2);
}

// Power heuristic with beta = 2 (Veach 1997) for the strategy of pdf a against pdf b.
LUMINA_INLINE float ptPowerHeuristic(float a, float b) {
    const float a2 = a * a;
    const float b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

LUMINA_GPU_NAMESPACE_END

#endif
