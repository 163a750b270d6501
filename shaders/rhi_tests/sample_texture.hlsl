// lumina-kernel: cs main
// Sampled textures and samplers: a 2D texture read with a point sampler and with Load, a
// 2D array read per layer, and a cube with 1x1 faces sampled along each face's axis (so the
// face order, not the texel addressing, is what is checked).
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "rhi_tests/rhi_tests_shared.h"

ConstantBuffer<SampleConstants> gConstants : register(b0);
Texture2D<float4> gTexture : register(t0);
Texture2DArray<float4> gArray : register(t1);
TextureCube<float4> gCube : register(t2);
SamplerState gPoint : register(s0);
RWStructuredBuffer<SampleResult> gResults : register(u0);

// +X, -X, +Y, -Y, +Z, -Z: the face order of both APIs.
static const float3 kFaceAxes[6] = {float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0),
                                    float3(0, -1, 0), float3(0, 0, 1),  float3(0, 0, -1)};

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint probe = id.x;
    if (probe >= gConstants.count) {
        return;
    }
    const uint2 texel = uint2(probe % gConstants.width, (probe / gConstants.width) % gConstants.height);
    const float2 uv = (float2(texel) + 0.5) / float2(gConstants.width, gConstants.height);
    SampleResult result;
    result.sampled2D = gTexture.SampleLevel(gPoint, uv, 0);
    // texel as it is, not int3(texel, 0): vkd3d-shader 2.1 (DXBC) confuses that int cast with the
    // float cast above and loads at the float's bits (docs/d3d12.md).
    result.loaded2D = gTexture[texel];
    result.arrayLayer = gArray.Load(int4(0, 0, probe % gConstants.layers, 0));
    result.cubeFace = gCube.SampleLevel(gPoint, kFaceAxes[probe % 6], 0);
    gResults[probe] = result;
}
