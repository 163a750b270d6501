// lumina-kernel: cs main
// Projects one cube face of a probe's radiance onto the nine SH basis functions: the sum over
// the face's texels of L(d) Y_k(d) dOmega, where dOmega is the texel's exact solid angle
// (shCubeTexelSolidAngle), into the face's slot of the partial sums. L is what the bake rendered
// (emission and shadowed direct light, the sky where no surface is) plus, when the bake asks for
// a bounce, albedo / pi x the grid's own irradiance at the surface seen (as the sweep began,
// so each sweep adds exactly one bounce). One group per face: each thread sums a strided set of
// texels in registers, then one groupshared tree reduction. (Summing into groupshared memory texel by texel
// made the projection 86 ms a bake frame at the high preset on the lent H200.)
#include "common/bindings.hlsli"
#include "sh_grid/sh_grid_shared.h"

ConstantBuffer<ShGridConstants> gGrid : register(b0);
Texture2D<float4> gRadiance : register(t0); // the face: linear radiance
Texture2D<float4> gAlbedo : register(t1);   // the face's GBuffer (read for the bounce)
Texture2D<float4> gNormal : register(t2);
Texture2D<float4> gPosition : register(t3);
// The bounce source: the grid as this sweep began.
StructuredBuffer<float4> gProbeCoefficients : register(t4);
RWStructuredBuffer<float4> gPartials : register(u0); // [face * 9 + k]: rgb
LUMINA_PUSH_CONSTANTS(ShGridFaceConstants, gFace);

#include "sh_grid/sh_grid_common.hlsli"

groupshared float3 gsSums[LUMINA_SH_GRID_PROJECT_GROUP * LUMINA_SH_GRID_COEFFICIENTS];

[numthreads(LUMINA_SH_GRID_PROJECT_GROUP, 1, 1)]
void main(uint thread : SV_GroupIndex) {
    float3 sums[LUMINA_SH_GRID_COEFFICIENTS];
    [unroll] for (uint k = 0u; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
        sums[k] = float3(0.0, 0.0, 0.0);
    }
    const uint size = gFace.faceSize;
    const float sizeF = float(size);
    for (uint texel = thread; texel < size * size; texel += LUMINA_SH_GRID_PROJECT_GROUP) {
        // One cast per value (docs/d3d12.md): the texel as int, its float derived from that.
        const int3 pixel = int3(int(texel % size), int(texel / size), 0);
        const float2 xy = float2(pixel.xy);
        const float u = 2.0 * (xy.x + 0.5) / sizeF - 1.0;
        const float v = 1.0 - 2.0 * (xy.y + 0.5) / sizeF;
        const float3 d = normalize(gFace.forward.xyz + u * gFace.right.xyz + v * gFace.up.xyz);
        float3 radiance = gRadiance.Load(pixel).rgb;
        if (gFace.bounce != 0u) {
            const float4 normal = gNormal.Load(pixel);
            if (normal.a > 0.5) {
                const float3 albedo = gAlbedo.Load(pixel).rgb;
                const float3 p = gPosition.Load(pixel).xyz;
                radiance += albedo * LUMINA_INV_PI * shGridIrradiance(p, normal.xyz);
            }
        }
        const float3 weighted = radiance * shCubeTexelSolidAngle(xy.x, xy.y, sizeF);
        // Unrolled, so every index into sums is a constant (docs/d3d12.md: no dynamic writes).
        [unroll] for (uint j = 0u; j < LUMINA_SH_GRID_COEFFICIENTS; ++j) {
            sums[j] += weighted * shBasis(j, d);
        }
    }
    [unroll] for (uint i = 0u; i < LUMINA_SH_GRID_COEFFICIENTS; ++i) {
        gsSums[thread * LUMINA_SH_GRID_COEFFICIENTS + i] = sums[i];
    }
    GroupMemoryBarrierWithGroupSync();
    for (uint stride = LUMINA_SH_GRID_PROJECT_GROUP / 2u; stride > 0u; stride >>= 1) {
        if (thread < stride) {
            for (uint i = 0u; i < LUMINA_SH_GRID_COEFFICIENTS; ++i) {
                gsSums[thread * LUMINA_SH_GRID_COEFFICIENTS + i] +=
                    gsSums[(thread + stride) * LUMINA_SH_GRID_COEFFICIENTS + i];
            }
        }
        GroupMemoryBarrierWithGroupSync();
    }
    if (thread < LUMINA_SH_GRID_COEFFICIENTS) {
        gPartials[gFace.face * LUMINA_SH_GRID_COEFFICIENTS + thread] = float4(gsSums[thread], 0.0);
    }
}
