// lumina-kernel: cs texture2d
// lumina-kernel: cs texture2dArray
// lumina-kernel: cs texture3d
// lumina-kernel: cs buffer
// The finite check of `lumina render --check-finite` (gi/core/finite_check.h): counts the
// components of one mip of a float texture (or of a buffer of float4) that are NaN or +-Inf, into
// gCounts[slot]. The test is on the bits (all exponent bits set), not isnan/isinf, so no compiler
// may assume finite maths and fold it away. A half-float texel that overflowed reads as +-Inf.
#include "common/bindings.hlsli"
#include "debug/finite_check_shared.h"

Texture2D<float4> gTexture2d : register(t0);
Texture2DArray<float4> gTexture2dArray : register(t1);
Texture3D<float4> gTexture3d : register(t2);
StructuredBuffer<float4> gBuffer : register(t3);
RWStructuredBuffer<uint> gCounts : register(u0);
LUMINA_PUSH_CONSTANTS(FiniteCheckConstants, gCheck);

// IEEE 754 binary32: exponent bits all ones is Inf (mantissa 0) or NaN (mantissa not 0).
static const uint kExponentBits = 0x7f800000u;

uint nonFiniteComponents(float4 v) {
    const uint4 bits = asuint(v) & kExponentBits;
    return uint(bits.x == kExponentBits) + uint(bits.y == kExponentBits) + uint(bits.z == kExponentBits) +
           uint(bits.w == kExponentBits);
}

void count(float4 v) {
    const uint bad = nonFiniteComponents(v);
    if (bad != 0u) {
        InterlockedAdd(gCounts[gCheck.slot.x], bad);
    }
}

bool inside(uint3 id) {
    return all(id < gCheck.extent.xyz);
}

[numthreads(LUMINA_FINITE_CHECK_GROUP_2D, LUMINA_FINITE_CHECK_GROUP_2D, 1)] void
texture2d(uint3 id
          : SV_DispatchThreadID) {
    if (inside(id)) {
        count(gTexture2d.Load(int3(id.xy, gCheck.extent.w)));
    }
}

    [numthreads(LUMINA_FINITE_CHECK_GROUP_2D, LUMINA_FINITE_CHECK_GROUP_2D, 1)] void texture2dArray(
        uint3 id
        : SV_DispatchThreadID) {
    if (inside(id)) {
        count(gTexture2dArray.Load(int4(id.xyz, gCheck.extent.w)));
    }
}

[numthreads(LUMINA_FINITE_CHECK_GROUP_3D, LUMINA_FINITE_CHECK_GROUP_3D, LUMINA_FINITE_CHECK_GROUP_3D)] void
texture3d(uint3 id
          : SV_DispatchThreadID) {
    if (inside(id)) {
        count(gTexture3d.Load(int4(id.xyz, gCheck.extent.w)));
    }
}

    [numthreads(LUMINA_FINITE_CHECK_GROUP_1D, 1, 1)] void buffer(uint3 id
                                                                 : SV_DispatchThreadID) {
    if (inside(id)) {
        count(gBuffer[id.x]);
    }
}
