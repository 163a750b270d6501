#ifndef LUMINA_INSTANCE_TRANSFORM_HLSLI
#define LUMINA_INSTANCE_TRANSFORM_HLSLI
// Instance transforms as GpuScene stores them (scene_shared.h): the top three rows of each
// matrix, so a transformed point is three dot products. One definition for every raster pass
// that pulls vertices (GBuffer, shadows, card capture).
#include "common/scene_shared.h"

float3 instancePointToWorld(GpuInstance instance, float3 objectPosition) {
    const float4 p = float4(objectPosition, 1.0);
    return float3(dot(instance.objectToWorld[0], p), dot(instance.objectToWorld[1], p),
                  dot(instance.objectToWorld[2], p));
}

// Not normalised: interpolate first, normalise in the pixel shader.
float3 instanceNormalToWorld(GpuInstance instance, float3 objectNormal) {
    return float3(dot(instance.normalToWorld[0].xyz, objectNormal), dot(instance.normalToWorld[1].xyz, objectNormal),
                  dot(instance.normalToWorld[2].xyz, objectNormal));
}

// A material texture layer of the scene's sRGB texture array (sampling decodes to linear);
// white where the material has no texture.
float3 sampleMaterialLayer(Texture2DArray<float4> textures, SamplerState materialSampler, uint layer, float2 uv) {
    if (layer == LUMINA_NO_TEXTURE_LAYER) {
        return float3(1.0, 1.0, 1.0);
    }
    return textures.Sample(materialSampler, float3(uv, float(layer))).rgb;
}

// The same with explicit texture-coordinate derivatives, for compute kernels (no implicit ones).
float3 sampleMaterialLayerGrad(Texture2DArray<float4> textures, SamplerState materialSampler, uint layer, float2 uv,
                               float2 uvDx, float2 uvDy) {
    float3 value = float3(1.0, 1.0, 1.0);
    if (layer != LUMINA_NO_TEXTURE_LAYER) {
#ifdef LUMINA_DXBC
        // vkd3d-shader 2.1 wants an array texture's derivatives as wide as its coordinate.
        value = textures.SampleGrad(materialSampler, float3(uv, float(layer)), float3(uvDx, 0.0), float3(uvDy, 0.0)).rgb;
#else
        value = textures.SampleGrad(materialSampler, float3(uv, float(layer)), uvDx, uvDy).rgb;
#endif
    }
    return value;
}

#endif // LUMINA_INSTANCE_TRANSFORM_HLSLI
