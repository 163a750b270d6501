// The grid's irradiance at a point: the eight probes of the cell around it, trilinearly weighted,
// each evaluated at the normal (docs/sh_grid.md, "Sampling"). Needs gGrid (ShGridConstants) and
// gProbeCoefficients (StructuredBuffer<float4>) declared by the including kernel.
#include "sh_grid/sh_grid_shared.h"

// E_probe(n) summed over the nine coefficients, the l = 1 and l = 2 bands windowed.
float3 shGridProbeIrradiance(uint probe, float3 n) {
    float3 sum = float3(0.0, 0.0, 0.0);
    for (uint k = 0u; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
        const uint band = shBand(k);
        const float window = band == 0u ? 1.0 : (band == 1u ? gGrid.windowBand1 : gGrid.windowBand2);
        sum += gProbeCoefficients[probe * LUMINA_SH_GRID_COEFFICIENTS + k].rgb * (window * shBasis(k, n));
    }
    return sum;
}

// Trilinear blend of the eight probes around p (clamped to the grid), evaluated at normal n,
// negative results clamped to 0.
float3 shGridIrradiance(float3 p, float3 n) {
    const int3 last = int3(gGrid.counts) - 1;
    const float3 g = (p - gGrid.origin) / gGrid.spacing;
    // One cast per value (docs/d3d12.md): the cell's corner as uint, the float derived from it.
    const uint3 base = uint3(clamp(int3(floor(g)), int3(0, 0, 0), last - 1));
    const float3 alpha = saturate(g - float3(base));
    float3 sum = float3(0.0, 0.0, 0.0);
    for (uint corner = 0u; corner < 8u; ++corner) {
        const uint3 offset = uint3(corner & 1u, (corner >> 1) & 1u, corner >> 2);
        const uint3 c = base + offset;
        const float3 w3 = lerp(1.0 - alpha, alpha, float3(offset));
        const uint probe = c.x + gGrid.counts.x * (c.y + gGrid.counts.y * c.z);
        sum += (w3.x * w3.y * w3.z) * shGridProbeIrradiance(probe, n);
    }
    return max(sum, float3(0.0, 0.0, 0.0));
}
