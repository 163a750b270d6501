#ifndef LUMINA_TONEMAP_SHARED_H
#define LUMINA_TONEMAP_SHARED_H
// The display transform, shared by the CPU image writers (gi/image/display.h) and the GPU
// composite, so a PNG written on the CPU and a frame tonemapped on the GPU use one curve:
//
//   display = srgbOetf(acesFitted(exposureScale * radiance))     per channel
//
// Written for C++20 and HLSL (DXC and glslang) through shared_types.h (lumina::gpu in C++):
// scalar functions do the work, float3 wrappers apply them per channel. NaN behaves the same on
// both sides because clamps are written as comparisons (a NaN fails every comparison).
// Compile-checked as HLSL by tests/image/tonemap_shared_check.hlsl. (Include guard, not
// #pragma once: glslang's preprocessor ignores the pragma. No parameter is called `linear`:
// it is an HLSL keyword.)

#include "shared_types.h"

// pow is not among the intrinsics shared_types.h mirrors.
#ifdef __cplusplus
#define LUMINA_TONEMAP_POW(a, b) std::pow(a, b)
#define LUMINA_TONEMAP_CONST inline constexpr
#else
#define LUMINA_TONEMAP_POW(a, b) pow(a, b)
#define LUMINA_TONEMAP_CONST static const
#endif

LUMINA_GPU_NAMESPACE_BEGIN

// ACES filmic curve as fitted by Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve"
// (blog post, 2016-01-06; CC0/MIT): a rational fit of ACES RRT+ODT (Rec.709, gamma removed),
// pre-exposed so that 1.0 maps to about 0.8. Input: linear Rec.709/sRGB radiance.
LUMINA_TONEMAP_CONST float kAcesFitA = 2.51f;
LUMINA_TONEMAP_CONST float kAcesFitB = 0.03f;
LUMINA_TONEMAP_CONST float kAcesFitC = 2.43f;
LUMINA_TONEMAP_CONST float kAcesFitD = 0.59f;
LUMINA_TONEMAP_CONST float kAcesFitE = 0.14f;
// The fitted curve crosses 1 at x ~= 7.24 and is clamped there, so any larger input gives 1;
// clamping the input at 64 keeps x*x*2.51 finite even in half precision on the GPU.
LUMINA_TONEMAP_CONST float kAcesFitMaxInput = 64.0f;

// sRGB opto-electronic transfer function, IEC 61966-2-1.
LUMINA_TONEMAP_CONST float kSrgbLinearLimit = 0.0031308f;
LUMINA_TONEMAP_CONST float kSrgbEncodedLimit = 0.04045f;

// v clamped to [lo, hi]; NaN gives lo.
LUMINA_INLINE float tonemapClamp(float v, float lo, float hi) {
    return v > lo ? (v < hi ? v : hi) : lo;
}

// Negative radiance would fold back to bright values through the rational curve: clamped to 0.
LUMINA_INLINE float acesFitted(float radiance) {
    const float x = tonemapClamp(radiance, 0.0f, kAcesFitMaxInput);
    return tonemapClamp((x * (kAcesFitA * x + kAcesFitB)) / (x * (kAcesFitC * x + kAcesFitD) + kAcesFitE),
                        0.0f, 1.0f);
}

// Linear [0,1] to sRGB-encoded [0,1].
LUMINA_INLINE float srgbOetf(float value) {
    const float v = tonemapClamp(value, 0.0f, 1.0f);
    if (v >= 1.0f) {
        return 1.0f; // exactly: in float, 1.055 * 1 - 0.055 rounds to 0.99999994
    }
    return v <= kSrgbLinearLimit ? 12.92f * v : 1.055f * LUMINA_TONEMAP_POW(v, 1.0f / 2.4f) - 0.055f;
}

// sRGB-encoded [0,1] to linear [0,1].
LUMINA_INLINE float srgbEotf(float encoded) {
    const float v = tonemapClamp(encoded, 0.0f, 1.0f);
    return v <= kSrgbEncodedLimit ? v / 12.92f : LUMINA_TONEMAP_POW((v + 0.055f) / 1.055f, 2.4f);
}

// exposureScale = 2^EV, computed once by the caller.
LUMINA_INLINE float tonemapToDisplay(float radiance, float exposureScale) {
    return srgbOetf(acesFitted(radiance * exposureScale));
}

LUMINA_INLINE float3 acesFitted3(float3 radiance) {
    return float3(acesFitted(radiance.x), acesFitted(radiance.y), acesFitted(radiance.z));
}

LUMINA_INLINE float3 srgbOetf3(float3 value) {
    return float3(srgbOetf(value.x), srgbOetf(value.y), srgbOetf(value.z));
}

LUMINA_INLINE float3 tonemapToDisplay3(float3 radiance, float exposureScale) {
    return float3(tonemapToDisplay(radiance.x, exposureScale), tonemapToDisplay(radiance.y, exposureScale),
                  tonemapToDisplay(radiance.z, exposureScale));
}

LUMINA_GPU_NAMESPACE_END

#undef LUMINA_TONEMAP_POW
#undef LUMINA_TONEMAP_CONST

#endif // LUMINA_TONEMAP_SHARED_H
