// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// GBuffer, first half: the visibility raster. Each pixel keeps only the id of the nearest
// triangle (deferred_shared.h) and depth; gbuffer_resolve.hlsl turns ids into the GBuffer's
// attributes in a compute pass. Why two passes: writing five targets from a pixel shader is
// bound by the raster back end (the lent H200 has few ROPs and runs pixel shaders on a few SMs
// only), while the resolve runs on every SM and writes each target once (docs/deferred.md).
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/scene_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(GBufferVisibilityDrawConstants, gDraw);
ConstantBuffer<DeferredFrameConstants> gFrame : register(b0);
StructuredBuffer<GpuVertex> gVertices : register(t0);
StructuredBuffer<GpuInstance> gInstances : register(t1);

float4 vsMain(uint vertexId : SV_VertexID) : SV_Position {
    const GpuVertex vertex = gVertices[vertexId];
    const float3 world = instancePointToWorld(gInstances[gDraw.instance], vertex.positionU.xyz);
    const float4 p = float4(world, 1.0);
    return float4(dot(gFrame.camera.viewProjRows[0], p), dot(gFrame.camera.viewProjRows[1], p),
                  dot(gFrame.camera.viewProjRows[2], p), dot(gFrame.camera.viewProjRows[3], p));
}

uint psMain(uint primitive : SV_PrimitiveID, bool isFrontFace : SV_IsFrontFace) : SV_Target0 {
    const uint id = gDraw.firstId + primitive;
    return isFrontFace ? (id | LUMINA_GBUFFER_FRONT_FACE) : id;
}
