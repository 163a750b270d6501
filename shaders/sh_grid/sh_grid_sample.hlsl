// lumina-kernel: cs main
// Irradiance per pixel from the probe grid: the eight probes around the pixel's surface,
// trilinear weights, each probe's SH evaluated at the normal (windowed bands), negative results
// clamped (sh_grid_common.hlsli). Sky pixels get 0.
#include "common/bindings.hlsli"
#include "sh_grid/sh_grid_shared.h"

ConstantBuffer<ShGridConstants> gGrid : register(b0);
Texture2D<float4> gNormal : register(t0);
Texture2D<float4> gPosition : register(t1);
StructuredBuffer<float4> gProbeCoefficients : register(t2);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gOut : register(u0); // rgb: irradiance E; a: 1 on surfaces

#include "sh_grid/sh_grid_common.hlsli"

[numthreads(LUMINA_SH_GRID_SAMPLE_GROUP, LUMINA_SH_GRID_SAMPLE_GROUP, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gGrid.width || id.y >= gGrid.height) {
        return;
    }
    const float4 normal = gNormal.Load(int3(int2(id.xy), 0));
    float4 result = float4(0.0, 0.0, 0.0, 0.0);
    if (normal.a > 0.5) {
        const float3 p = gPosition.Load(int3(int2(id.xy), 0)).xyz;
        result = float4(shGridIrradiance(p, normal.xyz), 1.0);
    }
    gOut[id.xy] = result;
}
