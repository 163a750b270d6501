// lumina-kernel: cs main
// A probe's nine irradiance coefficients from the six faces' partial projections: the radiance's
// coefficient L_k is their sum, the irradiance's E_k = A_l L_k (the clamped-cosine convolution
// done analytically, docs/sh_grid.md). One thread per coefficient.
#include "common/bindings.hlsli"
#include "sh_grid/sh_grid_shared.h"

StructuredBuffer<float4> gPartials : register(t0); // [face * 9 + k]
RWStructuredBuffer<float4> gProbeCoefficients : register(u0);
LUMINA_PUSH_CONSTANTS(ShGridCombineConstants, gCombine);

[numthreads(LUMINA_SH_GRID_COEFFICIENTS, 1, 1)]
void main(uint k : SV_GroupIndex) {
    float3 sum = float3(0.0, 0.0, 0.0);
    for (uint face = 0u; face < LUMINA_SH_GRID_FACES; ++face) {
        sum += gPartials[face * LUMINA_SH_GRID_COEFFICIENTS + k].rgb;
    }
    gProbeCoefficients[gCombine.probe * LUMINA_SH_GRID_COEFFICIENTS + k] = float4(shCosineBand(k) * sum, 0.0);
}
