#ifndef LUMINA_PT_MATERIAL_HLSLI
#define LUMINA_PT_MATERIAL_HLSLI
// Diffuse materials as GpuScene holds them: albedo = base colour x base-colour texture,
// emission (radiance) = emissive factor x emission texture. Textures live in one 2D array
// (RGBA8 sRGB, so sampling returns linear colour). The includer declares gTextures and
// gMaterialSampler (path_trace.hlsl).
#include "common/scene_shared.h"

float3 ptSampleMaterialTexture(uint layer, float2 uv) {
    if (layer == LUMINA_NO_TEXTURE_LAYER) {
        return float3(1.0f, 1.0f, 1.0f);
    }
    // Level 0: the reference filters textures through its own pixel integration.
    return gTextures.SampleLevel(gMaterialSampler, float3(uv, float(layer)), 0.0f).rgb;
}

float3 ptAlbedo(GpuMaterial m, float2 uv) {
    return m.baseColor.rgb * ptSampleMaterialTexture(m.textures.x, uv);
}

float3 ptEmission(GpuMaterial m, float2 uv) {
    if (m.emission.r <= 0.0f && m.emission.g <= 0.0f && m.emission.b <= 0.0f) {
        return float3(0.0f, 0.0f, 0.0f);
    }
    return m.emission.rgb * ptSampleMaterialTexture(m.textures.y, uv);
}

#endif
