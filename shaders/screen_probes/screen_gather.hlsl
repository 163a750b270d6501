// lumina-kernel: cs main
// Pass 11, final gather: irradiance at every pixel from the four probes around it. Weights:
// bilinear in the probe grid x exp(-plane distance / (filterPlaneScale x view depth)) x
// max(0, n . n_probe)^filterNormalPower, so a pixel reads probes on its own surface; each probe's tile of
// the irradiance atlas is sampled (hardware bilinear, the border makes it seamless) in the pixel's
// normal direction. Where no probe passes, the bilinear weights of the valid ones alone are used.
// Sky pixels get none. One thread per pixel; output irradiance, in the scene's radiance units x
// steradian (pi L under a uniform radiance L).
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<ScreenProbe> gProbes : register(t2);
Texture2D<float4> gIrradiance : register(t3);
SamplerState gLinearClamp : register(s0);
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gGather : register(u0); // rgb: irradiance; a: 1 on surfaces

// Total weight below which the surface-aware weights are not trusted.
#define LUMINA_SP_MIN_GATHER_WEIGHT 1e-4

float3 sampleProbe(uint probe, float3 n) {
    const float2 tile = float2(probe % gSp.probeGrid.x, probe / gSp.probeGrid.x) * float(LUMINA_SP_IRRADIANCE_TILE);
    const float2 e = octEncode(n);
    const float2 texel = tile + 1.0 + (e * 0.5 + 0.5) * float(LUMINA_SP_IRRADIANCE_SIZE);
    const float2 atlas = float2(gSp.probeGrid) * float(LUMINA_SP_IRRADIANCE_TILE);
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
    const float2 g = (float2(id.xy) + 0.5) / float(gSp.probeSpacing) - 0.5;
    const int2 base = int2(floor(g));
    const float2 f = g - float2(base);
    float3 surfaceSum = float3(0.0, 0.0, 0.0);
    float surfaceWeight = 0.0;
    float3 plainSum = float3(0.0, 0.0, 0.0);
    float plainWeight = 0.0;
    for (uint k = 0u; k < 4u; ++k) {
        const int2 corner = int2(k & 1u, k >> 1u);
        const int2 cell = clamp(base + corner, int2(0, 0), int2(gSp.probeGrid) - 1);
        const uint probe = uint(cell.y) * gSp.probeGrid.x + uint(cell.x);
        const ScreenProbe p = gProbes[probe];
        if (!probeIsValid(p)) {
            continue;
        }
        const float2 bw = lerp(1.0 - f, f, float2(corner));
        const float bilinear = bw.x * bw.y;
        const float planeDistance = abs(dot(position.xyz - p.positionAndDepth.xyz, p.normal.xyz));
        const float surface = exp(-planeDistance / (gSp.filterPlaneScale * position.w)) *
                              pow(saturate(dot(n, p.normal.xyz)), gSp.filterNormalPower);
        const float3 irradiance = sampleProbe(probe, n);
        surfaceSum += bilinear * surface * irradiance;
        surfaceWeight += bilinear * surface;
        plainSum += bilinear * irradiance;
        plainWeight += bilinear;
    }
    float3 result = float3(0.0, 0.0, 0.0);
    if (surfaceWeight > LUMINA_SP_MIN_GATHER_WEIGHT) {
        result = surfaceSum / surfaceWeight;
    } else if (plainWeight > 0.0) {
        result = plainSum / plainWeight;
    }
    gGather[id.xy] = float4(result, 1.0);
}
