#ifndef LUMINA_SP_ADAPTIVE_SHARE_SHARED_H
#define LUMINA_SP_ADAPTIVE_SHARE_SHARED_H
// How the adaptive allocation shares its slots when more tiles want an adaptive probe than there
// are slots, shared by C++ (tests) and HLSL (probe_adaptive_allocation.hlsl). The candidate of
// rank k in tile order (0-based) of `wanted` takes slot floor(k x slots / wanted), and is kept
// where that steps up from rank k - 1's: exactly `slots` candidates, spread evenly over the image in
// tile order, so its bottom rows keep their share instead of the top rows taking every slot.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

// floor(a x b / d) and its remainder, exact for any a and b and 0 < d < 2^31 where the quotient
// fits in 32 bits. Shader model 5 has no 64-bit integers and float division is not exact on every
// GPU, so the product is formed in two 32-bit halves and divided one bit at a time.
LUMINA_INLINE uint2 spMulDivRemainder(uint a, uint b, uint d) {
    const uint aLow = a & 0xffffu, aHigh = a >> 16u, bLow = b & 0xffffu, bHigh = b >> 16u;
    const uint lowLow = aLow * bLow, lowHigh = aLow * bHigh, highLow = aHigh * bLow;
    const uint middle = (lowLow >> 16u) + (lowHigh & 0xffffu) + (highLow & 0xffffu);
    const uint productLow = (lowLow & 0xffffu) | (middle << 16u);
    const uint productHigh = aHigh * bHigh + (lowHigh >> 16u) + (highLow >> 16u) + (middle >> 16u);
    uint quotient = 0u;
    uint remainder = 0u;
    for (uint bit = 0u; bit < 64u; ++bit) {
        const uint word = bit < 32u ? productHigh : productLow;
        remainder = (remainder << 1u) | ((word >> (31u - (bit & 31u))) & 1u);
        const bool fits = remainder >= d;
        remainder -= fits ? d : 0u;
        quotient = (quotient << 1u) | (fits ? 1u : 0u);
    }
    return uint2(quotient, remainder);
}

// The adaptive slot (0-based, below the uniform grid's) of the candidate of rank `rank` among
// `wanted` for `slots` slots, and 1 in y if it keeps it. rank < wanted.
LUMINA_INLINE uint2 spAdaptiveShare(uint rank, uint slots, uint wanted) {
    uint2 share = uint2(rank, rank < slots ? 1u : 0u);
    if (wanted > slots) {
        // floor((rank + 1) x slots / wanted) steps up past floor(rank x slots / wanted) exactly
        // where the remainder plus slots reaches wanted.
        const uint2 division = spMulDivRemainder(rank, slots, wanted);
        share = uint2(division.x, division.y + slots >= wanted ? 1u : 0u);
    }
    return share;
}

LUMINA_GPU_NAMESPACE_END

#endif
