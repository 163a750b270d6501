// lumina-kernel: cs main
// Pass 11, final gather: irradiance at every pixel from the four probes around it. Weights:
// bilinear in the probe grid x exp(-plane distance / (filterPlaneScale x view depth)) x
// max(0, n . n_probe)^filterNormalPower, so a pixel reads probes on its own surface; each probe's tile of
// the irradiance atlas is sampled (hardware bilinear, the border makes it seamless) in the pixel's
// normal direction. A pixel whose best corner probe weighs less than LUMINA_SP_ADAPTIVE_COVERAGE
// lies on no probe's surface (a thin wall between a jamb and a door, a silhouette against the sky):
// it also reads the adaptive probes of the 3 x 3 adaptive tiles around it, each weighted by a tent
// over two tiles' distance from the probe's pixel x its surface weight, faded in as the best corner
// weight falls below the threshold so that no seam shows where it starts. Where no probe passes,
// the bilinear weights of the valid ones alone are used.
// Sky pixels get none. One thread per pixel; output irradiance, in the scene's radiance units x
// steradian (pi L under a uniform radiance L).
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<ScreenProbe> gProbes : register(t2);
Texture2D<float4> gIrradiance : register(t3);
StructuredBuffer<uint> gAdaptiveIndex : register(t4); // per adaptive tile: its probe or none
SamplerState gLinearClamp : register(s0);
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gGather : register(u0); // rgb: irradiance; a: 1 on surfaces

// Total weight below which the surface-aware weights are not trusted.
#define LUMINA_SP_MIN_GATHER_WEIGHT 1e-4

float3 sampleProbe(uint probe, float3 n) {
    const float2 tile = float2(probe % gSp.probeGrid.x, probe / gSp.probeGrid.x) * float(LUMINA_SP_IRRADIANCE_TILE);
    const float2 e = octEncode(n);
    const float2 texel = tile + 1.0 + (e * 0.5 + 0.5) * float(LUMINA_SP_IRRADIANCE_SIZE);
    // The atlas holds every slot's tile: the uniform grid's rows, then the adaptive rows.
    const float2 atlas =
        float2(gSp.probeGrid.x, gSp.probeCount / gSp.probeGrid.x) * float(LUMINA_SP_IRRADIANCE_TILE);
    return gIrradiance.SampleLevel(gLinearClamp, texel / atlas, 0.0).rgb;
}

[numthreads(LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gSp.imageSize.x || id.y >= gSp.imageSize.y) {
        return;
    }
    const float4 normal = gNormal.Load(int3(id.xy, 0));
    const float4 position = gPosition.Load(int3(id.xy, 0));
    if (normal.w <= 0.0 || position.w <= 0.0) {
        gGather[id.xy] = float4(0.0, 0.0, 0.0, 0.0);
        return;
    }
    const float3 n = normalize(normal.xyz);
    float3 surfaceSum = float3(0.0, 0.0, 0.0);
    float surfaceWeight = 0.0;
    float3 plainSum = float3(0.0, 0.0, 0.0);
    float plainWeight = 0.0;
    float best = 0.0;
    for (uint k = 0u; k < 4u; ++k) {
        float bilinear;
        const uint probe = uniformCorner(id.xy, k, bilinear);
        const ScreenProbe p = gProbes[probe];
        if (probeIsValid(p)) {
            const float surface = probeSurfaceWeight(p, position, n);
            const float3 irradiance = sampleProbe(probe, n);
            surfaceSum += bilinear * surface * irradiance;
            surfaceWeight += bilinear * surface;
            plainSum += bilinear * irradiance;
            plainWeight += bilinear;
            best = max(best, surface);
        }
    }
    if (gSp.adaptiveSpacing > 0u && best < LUMINA_SP_ADAPTIVE_COVERAGE) {
        const float fade = 1.0 - best / LUMINA_SP_ADAPTIVE_COVERAGE;
        const float reach = 2.0 * float(gSp.adaptiveSpacing);
        const uint2 tiles = adaptiveGrid();
        const int2 tile = int2(id.xy / gSp.adaptiveSpacing);
        for (uint j = 0u; j < 9u; ++j) {
            const int2 at = tile + int2(int(j % 3u) - 1, int(j / 3u) - 1);
            const bool inside = all(at >= 0) && all(at < int2(tiles));
            const uint probe =
                inside ? gAdaptiveIndex[uint(at.y) * tiles.x + uint(at.x)] : LUMINA_SP_NO_ADAPTIVE_PROBE;
            if (probe != LUMINA_SP_NO_ADAPTIVE_PROBE) {
                const ScreenProbe p = gProbes[probe];
                const float distance = length(float2(id.xy) - float2(p.info.yz));
                const float w = fade * saturate(1.0 - distance / reach) * probeSurfaceWeight(p, position, n);
                if (w > 0.0) {
                    surfaceSum += w * sampleProbe(probe, n);
                    surfaceWeight += w;
                }
            }
        }
    }
    float3 result = float3(0.0, 0.0, 0.0);
    if (surfaceWeight > LUMINA_SP_MIN_GATHER_WEIGHT) {
        result = surfaceSum / surfaceWeight;
    } else if (plainWeight > 0.0) {
        result = plainSum / plainWeight;
    }
    gGather[id.xy] = float4(result, 1.0);
}
