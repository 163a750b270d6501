// lumina-kernel: vs vsMain
// Sun shadow map: depth only, every instance through the sun's orthographic projection
// (DeferredShadowConstants::sunViewProjRows). Depth 0 is nearest the sun.
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/scene_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(ShadowDrawConstants, gDraw);
ConstantBuffer<DeferredShadowConstants> gShadow : register(b1);
StructuredBuffer<GpuVertex> gVertices : register(t0);
StructuredBuffer<GpuInstance> gInstances : register(t1);

float4 vsMain(uint vertexId : SV_VertexID) : SV_Position {
    const GpuInstance instance = gInstances[gDraw.instance];
    const float4 world = float4(instancePointToWorld(instance, gVertices[vertexId].positionU.xyz), 1.0);
    return float4(dot(gShadow.sunViewProjRows[0], world), dot(gShadow.sunViewProjRows[1], world),
                  dot(gShadow.sunViewProjRows[2], world), dot(gShadow.sunViewProjRows[3], world));
}
