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
    float3 irradiance = float3(0.0, 0.0, 0.0);
    for (uint i = 0; i < gFrame.lightCount; ++i) {
        const DeferredLight light = gLights[i];
        const LightSample sample = evaluateLight(light.light, position);
        const float cosine = dot(normal.xyz, sample.direction);
        if (cosine > 0.0 && any(sample.irradiance > 0.0)) {
            irradiance += sample.irradiance * (cosine * shadowVisibility(light, position, normal.xyz));
        }
    }
    const float3 radiance = gMaterial.Load(pixel).rgb + albedo * LUMINA_INV_PI * irradiance;
    gDirect[id.xy] = float4(radiance, 1.0);
}
