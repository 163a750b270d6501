// lumina-kernel: cs main
// Pass 10, SH low-pass: the filtered radiance map of a probe projected onto L2 spherical
// harmonics in world space (9 coefficients per channel; the low-pass that removes the noise the
// filters left), then irradiance reconstructed from them (negatives clamped) into the probe's
// bordered full-octahedral tile of the irradiance atlas, for hardware bilinear sampling in the
// final gather. The map covers the probe's upper hemisphere; below it, and in texels with no data
// yet, the radiance is taken as the probe's mean radiance M. That leaves the irradiance at the
// probe normal exactly as the hemisphere alone gives it (in L2, a constant below the tangent plane
// adds pi M - pi M there), and gives pixels whose normal leans away from the probe's a neutral
// estimate instead of black. With I_tk the integral of Y_k over texel t and S_k the integral of
// Y_k over the sphere (2 sqrt(pi) for k = 0, else 0):
//     c_k = sum_t (L_t - M) I_tk + M S_k.
// One group per probe: thread t projects texel t, then evaluates tile texels t, t + 64.
#include "screen_probes/screen_probe_common.hlsli"

StructuredBuffer<ScreenProbe> gProbes : register(t0);
StructuredBuffer<float4> gFiltered : register(t1);
RWStructuredBuffer<float4> gSh : register(u0); // LUMINA_SH_COEFFICIENTS per probe: rgb per coefficient
// Tiles of LUMINA_SP_IRRADIANCE_TILE^2 texels, probe (x, y) at tile (x, y).
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gIrradiance : register(u1);

// Texel i's projection onto coefficient k at i * LUMINA_SH_COEFFICIENTS + k: one dimension, as
// vkd3d-shader reads a two-dimensional groupshared array at the wrong element (docs/d3d12.md).
groupshared float3 gsProjection[LUMINA_SP_PROBE_TEXELS * LUMINA_SH_COEFFICIENTS];
groupshared float4 gsRadiance[LUMINA_SP_PROBE_TEXELS]; // rgb x solid angle; a: solid angle where known
groupshared float3 gsSh[LUMINA_SH_COEFFICIENTS];

[numthreads(LUMINA_SP_PROBE_TEXELS, 1, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    const uint probe = probeIndexOfGroup(group);
    if (probe >= gSp.probeCount || !probeIsValid(gProbes[probe])) {
        return;
    }
    const ProbeFrame frame = probeFrame(gProbes[probe].normal.xyz);
    const uint tx = t % LUMINA_SP_OCT_SIZE;
    const uint ty = t / LUMINA_SP_OCT_SIZE;
    const float4 texel = gFiltered[probe * LUMINA_SP_PROBE_TEXELS + t];
    const float solidAngle = texelSolidAngle(t);
    gsRadiance[t] = texel.a > 0.0 ? float4(texel.rgb * solidAngle, solidAngle) : float4(0.0, 0.0, 0.0, 0.0);
    GroupMemoryBarrierWithGroupSync();
    float4 mean = float4(0.0, 0.0, 0.0, 0.0);
    for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
        mean += gsRadiance[i];
    }
    const float3 meanRadiance = mean.a > 0.0 ? mean.rgb / mean.a : float3(0.0, 0.0, 0.0);
    const float3 deviation = texel.a > 0.0 ? texel.rgb - meanRadiance : float3(0.0, 0.0, 0.0);
    const Sh9 integrals = hemiOctTexelShIntegrals(tx, ty, LUMINA_SP_OCT_SIZE, frame);
    for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
        gsProjection[t * LUMINA_SH_COEFFICIENTS + k] = deviation * integrals.v[k];
    }
    GroupMemoryBarrierWithGroupSync();
    if (t < LUMINA_SH_COEFFICIENTS) {
        float3 c = t == 0u ? meanRadiance * LUMINA_SH_SPHERE_INTEGRAL_0 : float3(0.0, 0.0, 0.0);
        // Unrolled: as a loop (vkd3d-shader makes every loop not marked [unroll] a [loop] for
        // DXBC), the sum never reached its store on D3D12 under Wine (docs/d3d12.md).
        [unroll] for (uint i = 0u; i < LUMINA_SP_PROBE_TEXELS; ++i) {
            c += gsProjection[i * LUMINA_SH_COEFFICIENTS + t];
        }
        gsSh[t] = c;
        gSh[probe * LUMINA_SH_COEFFICIENTS + t] = float4(c, 0.0);
    }
    GroupMemoryBarrierWithGroupSync();
    Sh9 r;
    Sh9 g;
    Sh9 b;
    for (uint k = 0u; k < LUMINA_SH_COEFFICIENTS; ++k) {
        r.v[k] = gsSh[k].x;
        g.v[k] = gsSh[k].y;
        b.v[k] = gsSh[k].z;
    }
    const uint2 tile = uint2(probe % gSp.probeGrid.x, probe / gSp.probeGrid.x) * LUMINA_SP_IRRADIANCE_TILE;
    const uint tileTexels = LUMINA_SP_IRRADIANCE_TILE * LUMINA_SP_IRRADIANCE_TILE;
    for (uint i = t; i < tileTexels; i += LUMINA_SP_PROBE_TEXELS) {
        const uint2 at = uint2(i % LUMINA_SP_IRRADIANCE_TILE, i / LUMINA_SP_IRRADIANCE_TILE);
        const float3 n = octDecode(octBorderedTexelPosition(at.x, at.y, LUMINA_SP_IRRADIANCE_SIZE));
        gIrradiance[tile + at] = float4(shIrradiance(r, g, b, n), 1.0);
    }
}
