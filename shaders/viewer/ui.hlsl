// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// The viewer's one graphics pipeline (app/viewer/ui_renderer.cpp): Dear ImGui's indexed
// triangles, vertices pulled from a byte buffer, colour x texture, alpha-blended. The frame
// itself is one of those textured rectangles (the background draw list), so the scene image,
// a debug view and every panel go through this pipeline on both APIs.
#include "common/bindings.hlsli"
#include "viewer/viewer_shared.h"

LUMINA_PUSH_CONSTANTS(UiConstants, gUi);
ByteAddressBuffer gVertices : register(t0);
Texture2D<float4> gTexture : register(t1);
SamplerState gSampler : register(s0);

struct Varyings {
    float4 position : SV_Position;
    float2 uv : TEXCOORD0;
    float4 color : COLOR0;
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    const uint offset = (gUi.vertexBase + vertexId) * LUMINA_UI_VERTEX_BYTES;
    const float2 pixel = asfloat(gVertices.Load2(offset));
    const float2 uv = asfloat(gVertices.Load2(offset + 8u));
    const uint packed = gVertices.Load(offset + 16u);
    Varyings output;
    output.position = float4(pixel * gUi.scale + gUi.translate, 0.0, 1.0);
    output.uv = uv;
    // ImGui packs colours as R in the low byte (IM_COL32).
    output.color = float4(packed & 0xFFu, (packed >> 8) & 0xFFu, (packed >> 16) & 0xFFu, packed >> 24) / 255.0;
    return output;
}

float4 psMain(Varyings input) : SV_Target0 {
    return input.color * gTexture.SampleLevel(gSampler, input.uv, 0.0);
}
