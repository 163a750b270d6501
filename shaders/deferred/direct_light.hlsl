// lumina-kernel: cs main
// Direct lighting from the GBuffer: emitted radiance plus, for every light, Lambert diffuse
// (albedo / pi x irradiance) times its shadow visibility. Pixels without a surface show the
// sky radiance. One thread per pixel; output is linear radiance (RGBA16F).
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
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gDirect : register(u0);

static const float kInvPi = 0.31830988618379067;

// One stored shadow value: layer < 0 reads the sun map, else a layer of the cube array.
float loadShadow(int layer, int2 texel) {
    return layer < 0 ? gSunShadow.Load(int3(texel, 0)) : gPointShadows.Load(int4(texel, layer, 0));
}

// 3x3 PCF: nine bilinearly weighted compare taps around uv, as 4x4 texel loads with separable
// weights (tap k at offset k - 1 spreads over texels k and k + 1): 1 - f, 1, 1, f for the
// columns base - 1 .. base + 2, summing to 3 per axis. Taps past the map's (or the cube face's)
// edge clamp to it rather than wrapping onto the next face.
float pcf3x3(int layer, float2 uv, float size, float receiver) {
    const int last = int(size) - 1;
    const float2 texel = uv * size - 0.5;
    const float2 base = floor(texel);
    const float2 f = texel - base;
    const float4 wx = float4(1.0 - f.x, 1.0, 1.0, f.x);
    const float4 wy = float4(1.0 - f.y, 1.0, 1.0, f.y);
    float lit = 0.0;
    [unroll] for (int j = 0; j < 4; ++j) {
        [unroll] for (int i = 0; i < 4; ++i) {
            const int2 at = clamp(int2(base) + int2(i - 1, j - 1), int2(0, 0), int2(last, last));
            lit += (receiver <= loadShadow(layer, at) ? 1.0 : 0.0) * wx[i] * wy[j];
        }
    }
    return lit / 9.0;
}

float sunVisibility(float3 position, float3 normal) {
    const float texelWorld = gShadow.sunMap.z;
    const float4 p = float4(position + normal * (LUMINA_SUN_NORMAL_OFFSET_TEXELS * texelWorld), 1.0);
    const float3 clip = float3(dot(gShadow.sunViewProjRows[0], p), dot(gShadow.sunViewProjRows[1], p),
                               dot(gShadow.sunViewProjRows[2], p));
    const float2 uv = float2(0.5 + 0.5 * clip.x, 0.5 - 0.5 * clip.y);
    if (any(uv < 0.0) || any(uv > 1.0) || clip.z > 1.0) {
        return 1.0; // outside the fitted map: nothing there casts a shadow
    }
    const float receiver = clip.z - LUMINA_SUN_DEPTH_BIAS_TEXELS * texelWorld / gShadow.sunMap.w;
    return pcf3x3(-1, uv, gShadow.sunMap.x, receiver);
}

float pointVisibility(uint cube, float3 position, float3 normal) {
    const float4 light = gShadow.pointLights[cube];
    // World size of one face texel at the receiver: a face spans 2 x its major-axis distance.
    const float texelWorld = 2.0 * length(position - light.xyz) * gShadow.pointMap.y;
    const float3 offset = position + normal * (LUMINA_POINT_NORMAL_OFFSET_TEXELS * texelWorld) - light.xyz;
    const float receiver = (length(offset) - LUMINA_POINT_DEPTH_BIAS_TEXELS * texelWorld) / light.w;
    if (receiver >= 1.0) {
        return 1.0; // beyond the shadow range (unlimited lights reach the whole scene)
    }
    const uint face = cubeFaceOf(offset);
    const int layer = int(cube * LUMINA_CUBE_FACE_COUNT + face);
    return pcf3x3(layer, cubeFaceUv(offset, face), gShadow.pointMap.x, receiver);
}

float shadowVisibility(DeferredLight light, float3 position, float3 normal) {
    const uint slot = light.shadow.x;
    if (slot == LUMINA_SHADOW_SLOT_NONE) {
        return 1.0;
    }
    if (lightType(light.light) == LUMINA_LIGHT_DIRECTIONAL) {
        return gShadow.sunMap.x > 0.0 ? sunVisibility(position, normal) : 1.0;
    }
    return slot < uint(gShadow.pointMap.w) ? pointVisibility(slot, position, normal) : 1.0;
}

[numthreads(LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gFrame.counts.y || id.y >= gFrame.counts.z) {
        return;
    }
    const int3 pixel = int3(id.xy, 0);
    const float4 normal = gNormal.Load(pixel);
    if (normal.w <= 0.0) {
        gDirect[id.xy] = float4(gFrame.sky.rgb, 1.0);
        return;
    }
    const float3 position = gPosition.Load(pixel).xyz;
    const float3 albedo = gAlbedo.Load(pixel).rgb;
    float3 irradiance = float3(0.0, 0.0, 0.0);
    for (uint i = 0; i < gFrame.counts.x; ++i) {
        const DeferredLight light = gLights[i];
        const LightSample sample = evaluateLight(light.light, position);
        const float cosine = dot(normal.xyz, sample.direction);
        if (cosine > 0.0 && any(sample.irradiance > 0.0)) {
            irradiance += sample.irradiance * (cosine * shadowVisibility(light, position, normal.xyz));
        }
    }
    const float3 radiance = gMaterial.Load(pixel).rgb + albedo * kInvPi * irradiance;
    gDirect[id.xy] = float4(radiance, 1.0);
}
