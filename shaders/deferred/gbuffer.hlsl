// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// GBuffer: one draw per submesh of an instance, vertices pulled by absolute index. Writes
// albedo (RGBA8: linear albedo, a = 1), world normal (RGBA16F: unit normal facing the side
// seen, a = 1), material (RGBA32F: emitted radiance, a = material index) and world position
// (RGBA32F: xyz, w = view depth along the camera's forward axis); background pixels keep
// the cleared zeros, so w = 0 marks "no surface" in the normal and position targets.
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/scene_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(GpuDrawConstants, gDraw);
ConstantBuffer<DeferredFrameConstants> gFrame : register(b0);
StructuredBuffer<GpuVertex> gVertices : register(t0);
StructuredBuffer<GpuInstance> gInstances : register(t1);
StructuredBuffer<GpuMaterial> gMaterials : register(t2);
Texture2DArray<float4> gTextures : register(t3);
SamplerState gMaterialSampler : register(s0);

struct Varyings {
    float4 position : SV_Position;
    float3 worldPosition : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float2 uv : TEXCOORD2;
};

struct GBufferTargets {
    float4 albedo : SV_Target0;
    float4 normal : SV_Target1;
    float4 material : SV_Target2;
    float4 position : SV_Target3;
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    const GpuVertex vertex = gVertices[vertexId];
    const GpuInstance instance = gInstances[gDraw.instance];
    const float3 world = instancePointToWorld(instance, vertex.positionU.xyz);
    const float3 normal = instanceNormalToWorld(instance, vertex.normalV.xyz);
    const float4 p = float4(world, 1.0);
    Varyings output;
    output.position = float4(dot(gFrame.camera.viewProjRows[0], p), dot(gFrame.camera.viewProjRows[1], p),
                             dot(gFrame.camera.viewProjRows[2], p), dot(gFrame.camera.viewProjRows[3], p));
    output.worldPosition = world;
    output.normal = normal;
    output.uv = float2(vertex.positionU.w, vertex.normalV.w);
    return output;
}

float3 sampleLayer(uint layer, float2 uv) {
    return sampleMaterialLayer(gTextures, gMaterialSampler, layer, uv);
}

GBufferTargets psMain(Varyings input, bool isFrontFace : SV_IsFrontFace) {
    const GpuInstance instance = gInstances[gDraw.instance];
    const GpuMaterial material = gMaterials[gDraw.material];
    float3 normal = normalize(input.normal);
    // A mirroring instance turns its front faces clockwise on screen; a back face is drawn only
    // for double-sided materials and is shaded with the normal turned towards the viewer.
    const bool mirrored = instance.info.y != 0u;
    const bool seenFromFront = isFrontFace != mirrored;
    if (!seenFromFront) {
        normal = -normal;
    }
    const float3 toSurface = input.worldPosition - cameraPosition(gFrame.camera);
    const float viewDepth = dot(toSurface, gFrame.camera.forwardAndAspect.xyz);

    GBufferTargets output;
    output.albedo = float4(material.baseColor.rgb * sampleLayer(material.textures.x, input.uv), 1.0);
    output.normal = float4(normal, 1.0);
    // Emission leaves the front face only unless double-sided (lights_shared.h); single-sided
    // back faces are culled, so only double-sided ones reach here seen from behind.
    const float3 emission = material.emission.rgb * sampleLayer(material.textures.y, input.uv);
    output.material = float4(emittedRadiance(emission, material.textures.z, seenFromFront ? 1.0 : -1.0),
                             float(gDraw.material));
    output.position = float4(input.worldPosition, viewDepth);
    return output;
}
