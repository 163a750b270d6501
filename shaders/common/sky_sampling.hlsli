#ifndef LUMINA_SKY_SAMPLING_HLSLI
#define LUMINA_SKY_SAMPLING_HLSLI
// The sky seen by every ray that leaves the scene: the deferred background, the path tracer's
// misses, screen-probe and surface-cache radiosity misses all call skyRadiance, so they agree.
// The sky is one RGBA32F latitude-longitude texture (gi/gpu_scene/sky_texture.h; a uniform sky
// is 1x1). Define LUMINA_SKY_TEXTURE as the kernel's Texture2D<float4> before including.
//
// Direction convention (gi/scene/scene.h, SkyEnvironment): longitude from -z towards +x about
// +y, u = 0.5 + atan2(x, -z) / (2 pi); polar angle from +y, v = acos(y) / pi; row 0 is the
// zenith. Bilinear between texel centres with Load (RGBA32F need not be filterable, and no
// sampler binding is needed): wrapping in longitude, clamped at the poles. gi/scene/
// sky_environment.cpp does the same lookup on the CPU.
#include "constants_shared.h"

float3 skyTexel(int2 texel, int2 size) {
    texel.x = (texel.x % size.x + size.x) % size.x;
    texel.y = clamp(texel.y, 0, size.y - 1);
    return LUMINA_SKY_TEXTURE.Load(int3(texel, 0)).rgb;
}

// The radiance arriving from `direction` (unit, world space).
float3 skyRadiance(float3 direction) {
    uint2 size;
    LUMINA_SKY_TEXTURE.GetDimensions(size.x, size.y);
    if (size.x == 1u && size.y == 1u) {
        return LUMINA_SKY_TEXTURE.Load(int3(0, 0, 0)).rgb; // uniform: exactly its radiance
    }
    float u = 0.5f + atan2(direction.x, -direction.z) / (2.0f * LUMINA_PI);
    float v = acos(clamp(direction.y, -1.0f, 1.0f)) / LUMINA_PI;
    // size is cast to int only, and the float size comes from that int: vkd3d-shader merges two
    // casts of one value and then reads one as the other (docs/d3d12.md).
    int2 texels = int2(size);
    float2 p = float2(u, v) * float2(texels) - 0.5f;
    float2 base = floor(p);
    float2 f = p - base;
    int2 t = int2(base);
    float3 top = lerp(skyTexel(t, texels), skyTexel(t + int2(1, 0), texels), f.x);
    float3 bottom = lerp(skyTexel(t + int2(0, 1), texels), skyTexel(t + int2(1, 1), texels), f.x);
    return lerp(top, bottom, f.y);
}

#endif
