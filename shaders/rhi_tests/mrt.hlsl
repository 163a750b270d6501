// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// Multiple render targets with depth: vertices pulled from a structured buffer, every
// attribute flat so that the test can predict each target's texels exactly.
#include "common/bindings.hlsli"
#include "rhi_tests/rhi_tests_shared.h"

LUMINA_PUSH_CONSTANTS(MrtPush, gPush);
StructuredBuffer<MrtVertex> gVertices : register(t0);

struct Varyings {
    float4 position : SV_Position;
    nointerpolation float4 color : COLOR0;
    nointerpolation float id : TEXCOORD0;
};

struct Targets {
    float4 color : SV_Target0;  // RGBA8_UNORM
    float4 scaled : SV_Target1; // RGBA16_FLOAT
    float id : SV_Target2;      // R32_FLOAT
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    const MrtVertex vertex = gVertices[vertexId];
    Varyings output;
    output.position = vertex.position;
    output.color = vertex.color;
    output.id = vertex.id.x;
    return output;
}

Targets psMain(Varyings input) {
    Targets output;
    output.color = input.color;
    output.scaled = input.color * gPush.tint;
    output.id = input.id;
    return output;
}
