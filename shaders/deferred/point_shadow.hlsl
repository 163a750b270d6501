// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// Point and spot light shadows: one face of one light's cube per raster pass (array layer
// 6 x cube + face), every instance drawn with both faces. The colour target (R32F) stores the
// linear distance to the light over the light's shadow range; depth (D32) only resolves
// visibility within the face.
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/scene_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(ShadowDrawConstants, gDraw);
ConstantBuffer<DeferredShadowConstants> gShadow : register(b1);
StructuredBuffer<GpuVertex> gVertices : register(t0);
StructuredBuffer<GpuInstance> gInstances : register(t1);

struct Varyings {
    float4 position : SV_Position;
    float3 offset : TEXCOORD0; // world position minus the light's
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    const GpuInstance instance = gInstances[gDraw.instance];
    const float3 world = instancePointToWorld(instance, gVertices[vertexId].positionU.xyz);
    const uint cube = gDraw.layer / LUMINA_CUBE_FACE_COUNT;
    const uint face = gDraw.layer % LUMINA_CUBE_FACE_COUNT;
    const ShadowedPointLight light = gShadow.pointLights[cube];
    Varyings output;
    output.offset = world - light.position;
    output.position = cubeFaceClip(output.offset, face, light.range * gShadow.pointNearFraction, light.range);
    return output;
}

float psMain(Varyings input) : SV_Target0 {
    const float range = gShadow.pointLights[gDraw.layer / LUMINA_CUBE_FACE_COUNT].range;
    return length(input.offset) / range;
}
