#ifndef LUMINA_LIGHTS_SHARED_H
#define LUMINA_LIGHTS_SHARED_H
// The one definition of Lumina's punctual lights and emissive surfaces, shared by the path
// tracer, the deferred renderer and C++ (docs/conventions.md). Units are those of
// gi/scene/units.h: emission and sky are radiance; a directional light's strength is the
// irradiance on a surface facing it; a point or spot light's strength I gives irradiance
// I / d^2 at d scene units on a surface facing it.
//
// evaluateLight(light, P) returns, for the surface point P, the unit direction towards the
// light, the distance to it (shadow rays stop there) and the irradiance the light delivers
// on a surface facing it. A Lambertian surface of albedo rho and unit normal n at P then
// leaves radiance rho / pi * irradiance * max(dot(n, direction), 0) (times visibility).
//
// Falloffs follow KHR_lights_punctual's recommended implementation:
//   - range (point, spot): window = saturate(1 - (d / range)^4), no window when range = 0;
//     the inverse-square law stays (irradiance = I * window / d^2);
//   - spot cone: t = saturate((cos(angle to axis) - cos(outer)) / max(cos(inner) - cos(outer),
//     1e-3)), attenuation = t * t (linear in cos between the cones, then squared);
//     packLight stores the scale and offset of t, as the extension's sample code does.
#include "scene_shared.h"
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_LIGHT_DIRECTIONAL 0u
#define LUMINA_LIGHT_POINT 1u
#define LUMINA_LIGHT_SPOT 2u
// Distance reported for a directional light: shadow rays towards it are unbounded.
#define LUMINA_LIGHT_INFINITE_DISTANCE 3.0e38f
// Smallest cos(inner) - cos(outer) of a spot cone (KHR_lights_punctual sample code).
#define LUMINA_SPOT_MIN_COS_DELTA 0.001f

struct GpuLight {
    float4 positionAndType;   // xyz: world position (point, spot); w: asfloat(LUMINA_LIGHT_*)
    float4 directionAndRange; // xyz: unit world direction the light travels (directional, spot);
                              // w: range in scene units, 0 for none
    float4 strength;          // rgb: colour x intensity (see above); w: unused
    float4 spotScaleOffset;   // x: 1 / max(cos inner - cos outer, 1e-3); y: -cos outer * x; zw: unused
};

LUMINA_STATIC_ASSERT_SIZE(GpuLight, 64);

struct LightSample {
    float3 direction;  // unit, from the surface point towards the light
    float distance;    // to the light, LUMINA_LIGHT_INFINITE_DISTANCE for a directional light
    float3 irradiance; // on a surface facing the light (before the cosine and visibility)
};

LUMINA_INLINE uint lightType(GpuLight light) {
    return asuint(light.positionAndType.w);
}

LUMINA_INLINE float lightSaturate(float x) {
    return min(max(x, 0.0f), 1.0f);
}

// KHR_lights_punctual range window; 1 when range is 0 (unlimited).
LUMINA_INLINE float lightRangeWindow(float distance, float range) {
    if (range <= 0.0f) {
        return 1.0f;
    }
    const float ratio = distance / range;
    const float ratio2 = ratio * ratio;
    return lightSaturate(1.0f - ratio2 * ratio2);
}

// KHR_lights_punctual spot attenuation for the cosine between the spot axis and the
// direction from the light to the surface point.
LUMINA_INLINE float lightSpotAttenuation(GpuLight light, float cosAngle) {
    const float t = lightSaturate(cosAngle * light.spotScaleOffset.x + light.spotScaleOffset.y);
    return t * t;
}

LUMINA_INLINE LightSample evaluateLight(GpuLight light, float3 position) {
    LightSample result;
    const float3 strength = float3(light.strength.x, light.strength.y, light.strength.z);
    const float3 travel =
        float3(light.directionAndRange.x, light.directionAndRange.y, light.directionAndRange.z);
    const uint type = lightType(light);
    if (type == LUMINA_LIGHT_DIRECTIONAL) {
        result.direction = -travel;
        result.distance = LUMINA_LIGHT_INFINITE_DISTANCE;
        result.irradiance = strength;
        return result;
    }
    const float3 toLight =
        float3(light.positionAndType.x, light.positionAndType.y, light.positionAndType.z) - position;
    const float distance2 = dot(toLight, toLight);
    const float distance = sqrt(distance2);
    result.direction = distance > 0.0f ? toLight * (1.0f / distance) : float3(0.0f, 0.0f, 0.0f);
    result.distance = distance;
    float attenuation =
        distance2 > 0.0f ? lightRangeWindow(distance, light.directionAndRange.w) / distance2 : 0.0f;
    if (type == LUMINA_LIGHT_SPOT) {
        attenuation *= lightSpotAttenuation(light, -dot(result.direction, travel));
    }
    result.irradiance = strength * attenuation;
    return result;
}

// Emission leaves the front face only (counter-clockwise winding, mirrored instances
// flipped) unless the material is double-sided. cosFront: cosine between the front-face
// geometric normal and the direction towards the viewer; materialFlags: GpuMaterial.textures.z.
LUMINA_INLINE float3 emittedRadiance(float3 emission, uint materialFlags, float cosFront) {
    const bool doubleSided = (materialFlags & LUMINA_MATERIAL_DOUBLE_SIDED) != 0u;
    return (cosFront > 0.0f || doubleSided) ? emission : float3(0.0f, 0.0f, 0.0f);
}

LUMINA_GPU_NAMESPACE_END

#endif
