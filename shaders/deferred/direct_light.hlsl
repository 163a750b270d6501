// lumina-kernel: cs main
// Direct lighting from the GBuffer: emitted radiance plus, for every light, Lambert diffuse
// (albedo / pi x irradiance) times its shadow visibility. Pixels without a surface show the
// sky along their camera ray (common/sky_sampling.hlsli). One thread per pixel; output is linear radiance
// (RGBA16F).
#include "common/bindings.hlsli"
#include "deferred/deferred_shared.h"

ConstantBuffer<DeferredFrameConstants> gFrame : register(b0);
ConstantBuffer<DeferredShadowConstants> gShadow : register(b1);
Texture2D<float4> gAlbedo : register(t0);
Texture2D<float4> gNormal : register(t1);
Texture2D<float4> gMaterial : register(t2);
Texture2D<float4> gPosition : register(t3);
Texture2D<float> gSunShadow : register(t4);          // D32, depth 0 nearest the sun
Texture2DArray<float> gPointShadows : register(t5);  // R32F cube array seen as 2D array layers
StructuredBuffer<DeferredLight> gLights : register(t6);
Texture2D<float4> gSky : register(t7);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gDirect : register(u0);


#define LUMINA_SHADOW_CONSTANTS gShadow
#define LUMINA_SUN_SHADOW_MAP gSunShadow
#define LUMINA_POINT_SHADOW_MAPS gPointShadows
#include "deferred/shadow_visibility.hlsli"
#define LUMINA_SKY_TEXTURE gSky
#include "common/sky_sampling.hlsli"

// The one of a pixel's two neighbours along `axis` (one pixel along x or y) that lies nearer the
// plane of the pixel's shading normal, as the world-space difference towards +axis; w = 0 when
// neither is a surface within 30 degrees of that plane (an edge, a silhouette, a feature a pixel
// wide).
float4 planeTangent(int2 pixel, int2 axis, float3 position, float3 normal) {
    float4 best = float4(0.0, 0.0, 0.0, 0.0);
    float bestOffPlane = 0.5; // sin 30 degrees
    [unroll] for (int side = -1; side <= 1; side += 2) {
        const int2 at = pixel + side * axis;
        if (any(at < 0) || at.x >= int(gFrame.width) || at.y >= int(gFrame.height)) {
            continue;
        }
        const float4 neighbour = gPosition.Load(int3(at, 0));
        const float3 towards = neighbour.xyz - position;
        const float gap = length(towards);
        if (neighbour.w <= 0.0 || gap <= 0.0) {
            continue;
        }
        const float offPlane = abs(dot(towards, normal)) / gap;
        if (offPlane < bestOffPlane) {
            bestOffPlane = offPlane;
            best = float4(towards * float(side), 1.0);
        }
    }
    return best;
}

// The normal of the surface's own triangles at a pixel, from the GBuffer positions of its
// neighbours (the sun's shadow compares with that plane, shadow_visibility.hlsli); w = 0 where
// the neighbours do not give one, or give one more than 30 degrees from the shading normal.
float4 geometricNormal(int2 pixel, float3 position, float3 normal) {
    const float4 alongX = planeTangent(pixel, int2(1, 0), position, normal);
    const float4 alongY = planeTangent(pixel, int2(0, 1), position, normal);
    if (alongX.w == 0.0 || alongY.w == 0.0) {
        return float4(normal, 0.0);
    }
    const float3 perpendicular = cross(alongX.xyz, alongY.xyz);
    const float size = length(perpendicular);
    if (size <= 0.0) {
        return float4(normal, 0.0);
    }
    float3 n = perpendicular / size;
    n = dot(n, normal) < 0.0 ? -n : n;
    return float4(n, dot(n, normal) >= 0.866 ? 1.0 : 0.0);
}

[numthreads(LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gFrame.width || id.y >= gFrame.height) {
        return;
    }
    const int3 pixel = int3(id.xy, 0);
    const float4 normal = gNormal.Load(pixel);
    if (normal.w <= 0.0) {
        const float3 view = cameraRayDirection(gFrame.camera, float2(id.xy) + 0.5);
        gDirect[id.xy] = float4(skyRadiance(view), 1.0);
        return;
    }
    const float3 position = gPosition.Load(pixel).xyz;
    const float3 albedo = gAlbedo.Load(pixel).rgb;
    // Only the sun's map compares with the plane (4 more position loads a pixel).
    const float4 plane =
        gShadow.sunMapSize > 0.0 ? geometricNormal(int2(id.xy), position, normal.xyz) : float4(normal.xyz, 0.0);
    float3 irradiance = float3(0.0, 0.0, 0.0);
    for (uint i = 0; i < gFrame.lightCount; ++i) {
        const DeferredLight light = gLights[i];
        const LightSample sample = evaluateLight(light.light, position);
        const float cosine = dot(normal.xyz, sample.direction);
        if (cosine > 0.0 && any(sample.irradiance > 0.0)) {
            const float visibility =
                shadowVisibilityOnPlane(light, position, normal.xyz, plane.xyz, plane.w > 0.0);
            irradiance += sample.irradiance * (cosine * visibility);
        }
    }
    const float3 radiance = gMaterial.Load(pixel).rgb + albedo * LUMINA_INV_PI * irradiance;
    gDirect[id.xy] = float4(radiance, 1.0);
}
