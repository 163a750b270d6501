// lumina-kernel: cs main
// GBuffer, second half: from each pixel's triangle id (gbuffer_visibility.hlsl) the attributes
// the raster used to interpolate. The camera ray through the pixel centre meets the triangle's
// plane at barycentrics that are perspective-correct by construction; the rays through the next
// pixel right and down give the texture-coordinate derivatives that pick the mip the pixel
// shader's implicit derivatives picked. Writes albedo (linear, a = 1), world normal (unit,
// facing the side seen, a = 1), material (emitted radiance, a = material index) and world
// position (w = view depth along the camera's forward axis); zeros where no surface, so w = 0
// marks "no surface" in the normal and position targets.
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/scene_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(GBufferResolveConstants, gConstants);
ConstantBuffer<DeferredFrameConstants> gFrame : register(b0);
Texture2D<uint> gVisibility : register(t0);
StructuredBuffer<GBufferResolveDraw> gDraws : register(t1);
StructuredBuffer<uint> gIndices : register(t2);
StructuredBuffer<GpuVertex> gVertices : register(t3);
StructuredBuffer<GpuInstance> gInstances : register(t4);
StructuredBuffer<GpuMaterial> gMaterials : register(t5);
Texture2DArray<float4> gTextures : register(t6);
SamplerState gMaterialSampler : register(s0);
LUMINA_UAV_FORMAT(rgba8) RWTexture2D<float4> gAlbedo : register(u0);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gNormal : register(u1);
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gMaterialOut : register(u2);
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gPosition : register(u3);

// The draw whose ids hold `id`: the last one with firstId <= id (the table is sorted).
GBufferResolveDraw findDraw(uint id) {
    uint low = 0u;
    uint high = gConstants.drawCount - 1u;
    [loop] while (low < high) {
        const uint middle = (low + high + 1u) >> 1;
        if (gDraws[middle].firstId <= id) {
            low = middle;
        } else {
            high = middle - 1u;
        }
    }
    return gDraws[low];
}

// Barycentrics (b1, b2) of the point where the ray meets the plane of the triangle p0 + b1 e1
// + b2 e2 (Moller-Trumbore without the inside test: the raster already chose the triangle).
float2 planeBarycentrics(float3 origin, float3 direction, float3 p0, float3 e1, float3 e2) {
    const float3 p = cross(direction, e2);
    const float determinant = dot(e1, p);
    // Seen edge-on the plane holds the ray; the raster covers no pixel centre then, but a
    // rounding case falls back to the centroid rather than dividing by zero.
    const bool edgeOn = abs(determinant) <= 1.0e-20;
    const float inverse = edgeOn ? 0.0 : 1.0 / determinant;
    const float3 t = origin - p0;
    const float3 q = cross(t, e1);
    const float2 b = float2(dot(t, p), dot(direction, q)) * inverse;
    return edgeOn ? float2(1.0 / 3.0, 1.0 / 3.0) : b;
}

float3 sampleLayer(uint layer, float2 uv, float2 uvDx, float2 uvDy) {
    return sampleMaterialLayerGrad(gTextures, gMaterialSampler, layer, uv, uvDx, uvDy);
}

struct WorldTriangle {
    float3 p0, e1, e2;    // world corner and edges
    float3 n0, n1, n2;    // world normals, not normalised
    float2 uv0, duv1, duv2;
};

WorldTriangle loadTriangle(GBufferResolveDraw draw, uint triangleInDraw, GpuInstance instance) {
    const uint first = draw.firstIndex + 3u * triangleInDraw;
    const GpuVertex v0 = gVertices[gIndices[first]];
    const GpuVertex v1 = gVertices[gIndices[first + 1u]];
    const GpuVertex v2 = gVertices[gIndices[first + 2u]];
    const float3 p0 = instancePointToWorld(instance, v0.positionU.xyz);
    WorldTriangle t;
    t.p0 = p0;
    t.e1 = instancePointToWorld(instance, v1.positionU.xyz) - p0;
    t.e2 = instancePointToWorld(instance, v2.positionU.xyz) - p0;
    t.n0 = instanceNormalToWorld(instance, v0.normalV.xyz);
    t.n1 = instanceNormalToWorld(instance, v1.normalV.xyz);
    t.n2 = instanceNormalToWorld(instance, v2.normalV.xyz);
    t.uv0 = float2(v0.positionU.w, v0.normalV.w);
    t.duv1 = float2(v1.positionU.w, v1.normalV.w) - t.uv0;
    t.duv2 = float2(v2.positionU.w, v2.normalV.w) - t.uv0;
    return t;
}

float2 uvAt(WorldTriangle t, float2 b) {
    return t.uv0 + b.x * t.duv1 + b.y * t.duv2;
}

[numthreads(LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gConstants.width || id.y >= gConstants.height) {
        return;
    }
    const uint visibility = gVisibility.Load(int3(id.xy, 0));
    float4 albedo = float4(0.0, 0.0, 0.0, 0.0);
    float4 normalOut = float4(0.0, 0.0, 0.0, 0.0);
    float4 materialOut = float4(0.0, 0.0, 0.0, 0.0);
    float4 position = float4(0.0, 0.0, 0.0, 0.0);
    if (visibility != 0u) {
        const uint triangleId = visibility & LUMINA_GBUFFER_ID_MASK;
        const GBufferResolveDraw draw = findDraw(triangleId);
        const GpuInstance instance = gInstances[draw.instance];
        const GpuMaterial material = gMaterials[draw.material];
        const WorldTriangle t = loadTriangle(draw, triangleId - draw.firstId, instance);

        const float3 eye = cameraPosition(gFrame.camera);
        const float2 pixel = float2(id.xy) + 0.5;
        const float2 b = planeBarycentrics(eye, cameraRayDirection(gFrame.camera, pixel), t.p0, t.e1, t.e2);
        const float2 bRight =
            planeBarycentrics(eye, cameraRayDirection(gFrame.camera, pixel + float2(1.0, 0.0)), t.p0, t.e1, t.e2);
        const float2 bDown =
            planeBarycentrics(eye, cameraRayDirection(gFrame.camera, pixel + float2(0.0, 1.0)), t.p0, t.e1, t.e2);
        // Inside the triangle up to rounding: clamped so that a silhouette pixel does not
        // extrapolate its attributes.
        const float2 bInside = saturate(b);
        const float2 bClamped = bInside / max(1.0, bInside.x + bInside.y);
        const float b0 = 1.0 - bClamped.x - bClamped.y;

        const float3 world = t.p0 + bClamped.x * t.e1 + bClamped.y * t.e2;
        float3 normal = normalize(b0 * t.n0 + bClamped.x * t.n1 + bClamped.y * t.n2);
        // A mirroring instance turns its front faces clockwise on screen; a back face is drawn
        // only for double-sided materials and is shaded with the normal turned to the viewer.
        const bool isFrontFace = (visibility & LUMINA_GBUFFER_FRONT_FACE) != 0u;
        const bool mirrored = instance.info.y != 0u;
        const bool seenFromFront = isFrontFace != mirrored;
        if (!seenFromFront) {
            normal = -normal;
        }
        const float2 uv = uvAt(t, bClamped);
        const float2 uvDx = uvAt(t, bRight) - uvAt(t, b);
        const float2 uvDy = uvAt(t, bDown) - uvAt(t, b);

        albedo = float4(material.baseColor.rgb * sampleLayer(material.textures.x, uv, uvDx, uvDy), 1.0);
        normalOut = float4(normal, 1.0);
        // Emission leaves the front face only unless double-sided (lights_shared.h).
        const float3 emission = material.emission.rgb * sampleLayer(material.textures.y, uv, uvDx, uvDy);
        materialOut = float4(emittedRadiance(emission, material.textures.z, seenFromFront ? 1.0 : -1.0),
                             float(draw.material));
        position = float4(world, dot(world - eye, gFrame.camera.forward));
    }
    gAlbedo[id.xy] = albedo;
    gNormal[id.xy] = normalOut;
    gMaterialOut[id.xy] = materialOut;
    gPosition[id.xy] = position;
}
