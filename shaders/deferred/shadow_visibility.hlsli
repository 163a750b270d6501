#ifndef LUMINA_SHADOW_VISIBILITY_HLSLI
#define LUMINA_SHADOW_VISIBILITY_HLSLI
// Shadow-map visibility of a light at a surface point: the deferred renderer's sun map and
// point-light cube maps (gi/deferred/sun_shadow_pass.h, point_shadow_pass.h) with their biases
// and 3x3 PCF, shared by every pass that lights surfaces with them (the deferred direct light,
// the surface cache's direct light), so that they all see the same shadows.
//
// The includer names its resources first:
//
//   ConstantBuffer<DeferredShadowConstants> gShadow;
//   Texture2D<float> gSunShadow;          // D32, depth 0 nearest the sun
//   Texture2DArray<float> gPointShadows;  // R32F cube array seen as 2D array layers
//   #define LUMINA_SHADOW_CONSTANTS gShadow
//   #define LUMINA_SUN_SHADOW_MAP gSunShadow
//   #define LUMINA_POINT_SHADOW_MAPS gPointShadows
//   #include "deferred/shadow_visibility.hlsli"
#include "deferred/deferred_shared.h"

#if !defined(LUMINA_SHADOW_CONSTANTS) || !defined(LUMINA_SUN_SHADOW_MAP) || !defined(LUMINA_POINT_SHADOW_MAPS)
#error "define LUMINA_SHADOW_CONSTANTS, LUMINA_SUN_SHADOW_MAP and LUMINA_POINT_SHADOW_MAPS before including shadow_visibility.hlsli"
#endif

// One stored shadow value: layer < 0 reads the sun map, else a layer of the cube array.
float loadShadow(int layer, int2 texel) {
    return layer < 0 ? LUMINA_SUN_SHADOW_MAP.Load(int3(texel, 0)) : LUMINA_POINT_SHADOW_MAPS.Load(int4(texel, layer, 0));
}

// 3x3 PCF: nine bilinearly weighted compare taps around uv, as 4x4 texel loads with separable
// weights (tap k at offset k - 1 spreads over texels k and k + 1): 1 - f, 1, 1, f for the
// columns base - 1 .. base + 2, summing to 3 per axis. Taps past the map's (or the cube face's)
// edge clamp to it rather than wrapping onto the next face.
//
// A texel where nothing was drawn (still at the clear value, 1: "as far as the map reaches")
// lies past the edge of every surface, the receiver's included, so it says nothing about the
// receiver's shadow and is left out of the average. Counted as lit, it let the sun through a
// zero-thickness wall at its foot: a floor point beside the wall has the wall on one side of its
// footprint and, beyond the wall's outside face, the empty texels of rays that miss everything.
//
// receiverSlope is the receiver's depth change per texel step along the map's x and y (zero
// for a receiver compared at one depth): each texel is then compared with the receiver's plane
// at that texel's centre.
float pcf3x3(int layer, float2 uv, float size, float receiver, float2 receiverSlope) {
    const int last = int(size) - 1;
    const float2 texel = uv * size - 0.5;
    const float2 base = floor(texel);
    const float2 f = texel - base;
    const float4 wx = float4(1.0 - f.x, 1.0, 1.0, f.x);
    const float4 wy = float4(1.0 - f.y, 1.0, 1.0, f.y);
    float lit = 0.0;
    float counted = 0.0;
    [unroll] for (int j = 0; j < 4; ++j) {
        [unroll] for (int i = 0; i < 4; ++i) {
            const int2 offset = int2(i - 1, j - 1);
            const int2 at = clamp(int2(base) + offset, int2(0, 0), int2(last, last));
            const float stored = loadShadow(layer, at);
            const float weight = stored < 1.0 ? wx[i] * wy[j] : 0.0;
            const float plane = receiver + dot(receiverSlope, base + float2(offset) - texel);
            lit += plane <= stored ? weight : 0.0;
            counted += weight;
        }
    }
    // Every tap empty: a receiver thinner than a texel, which nothing drawn can shadow.
    return counted > 0.0 ? lit / counted : 1.0;
}

// The sun map's depth change per texel step along its x and y over a plane of normal
// planeNormal. The map is orthographic: rows 0 and 1 of sunViewProjRows are its right and up axes
// over half its extent, row 2 the sun's direction over the depth range. One texel along x moves
// texelWorld along right (along y: down); staying on the plane then moves -n.step / n.sun along
// the sun. Called only for planes within LUMINA_SUN_PLANE_MIN_COSINE of the sun (sunVisibility),
// so facing = n.sun is at most -0.34 and the division stays small.
float2 sunReceiverSlope(float3 planeNormal, float facing, float texelWorld) {
    const float3 right = normalize(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[0].xyz);
    const float3 up = normalize(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[1].xyz);
    const float2 across = float2(dot(planeNormal, right), -dot(planeNormal, up));
    return -across * texelWorld / (facing * LUMINA_SHADOW_CONSTANTS.sunDepthRange);
}

// The sun's visibility at a surface point. Given the plane of the surface's own geometry
// (hasPlane: planeNormal is the normal of the triangles around the point, not an interpolated
// shading normal, which on a curved mesh differs from its facets enough to shadow them) the taps
// are compared with that plane and the point is not moved. Without it, or for a plane lit at a
// grazing angle (over 70 degrees from the sun, where a small error in the plane is many texels of
// depth), the point is moved along its normal by the normal offset, which keeps such surfaces
// free of acne but lifts a floor point beside a wall above the wall's foot.
float sunVisibility(float3 position, float3 normal, float3 planeNormal, bool hasPlane) {
    const float texelWorld = LUMINA_SHADOW_CONSTANTS.sunTexelWorld;
    const float3 sun = normalize(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[2].xyz);
    const float facing = dot(planeNormal, sun);
    const bool onPlane = hasPlane && facing <= -LUMINA_SUN_PLANE_MIN_COSINE;
    const float offset = onPlane ? 0.0 : LUMINA_SUN_NORMAL_OFFSET_TEXELS * texelWorld;
    const float4 p = float4(position + normal * offset, 1.0);
    const float3 clip = float3(dot(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[0], p), dot(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[1], p),
                               dot(LUMINA_SHADOW_CONSTANTS.sunViewProjRows[2], p));
    const float2 uv = float2(0.5 + 0.5 * clip.x, 0.5 - 0.5 * clip.y);
    if (any(uv < 0.0) || any(uv > 1.0) || clip.z > 1.0) {
        return 1.0; // outside the fitted map: nothing there casts a shadow
    }
    const float2 slope = onPlane ? sunReceiverSlope(planeNormal, facing, texelWorld) : float2(0.0, 0.0);
    const bool flat = onPlane && dot(planeNormal, normal) >= LUMINA_SUN_FLAT_MIN_COSINE;
    const float biasTexels = flat ? LUMINA_SUN_FLAT_DEPTH_BIAS_TEXELS : LUMINA_SUN_DEPTH_BIAS_TEXELS;
    const float depthBias = biasTexels * texelWorld / LUMINA_SHADOW_CONSTANTS.sunDepthRange;
    const float receiver = clip.z - depthBias - LUMINA_SUN_SLOPE_BIAS * length(slope);
    return pcf3x3(-1, uv, LUMINA_SHADOW_CONSTANTS.sunMapSize, receiver, slope);
}

float pointVisibility(uint cube, float3 position, float3 normal) {
    const ShadowedPointLight light = LUMINA_SHADOW_CONSTANTS.pointLights[cube];
    // World size of one face texel at the receiver: a face spans 2 x its major-axis distance.
    const float texelWorld = 2.0 * length(position - light.position) * LUMINA_SHADOW_CONSTANTS.pointFaceInvSize;
    const float3 offset = position + normal * (LUMINA_POINT_NORMAL_OFFSET_TEXELS * texelWorld) - light.position;
    const float receiver = (length(offset) - LUMINA_POINT_DEPTH_BIAS_TEXELS * texelWorld) / light.range;
    if (receiver >= 1.0) {
        return 1.0; // beyond the shadow range (unlimited lights reach the whole scene)
    }
    const uint face = cubeFaceOf(offset);
    const int layer = int(cube * LUMINA_CUBE_FACE_COUNT + face);
    const float2 flat = float2(0.0, 0.0); // the cube faces are not affine: no receiver plane
    return pcf3x3(layer, cubeFaceUv(offset, face), LUMINA_SHADOW_CONSTANTS.pointFaceSize, receiver, flat);
}

// planeNormal / hasPlane: the plane of the surface's own triangles where the caller knows it
// (the deferred direct light, from the GBuffer's positions); the sun's map then needs no normal
// offset (sunVisibility).
float shadowVisibilityOnPlane(DeferredLight light, float3 position, float3 normal, float3 planeNormal,
                              bool hasPlane) {
    const uint slot = light.shadowSlot;
    if (slot == LUMINA_SHADOW_SLOT_NONE) {
        return 1.0;
    }
    if (lightType(light.light) == LUMINA_LIGHT_DIRECTIONAL) {
        const bool hasMap = LUMINA_SHADOW_CONSTANTS.sunMapSize > 0.0;
        return hasMap ? sunVisibility(position, normal, planeNormal, hasPlane) : 1.0;
    }
    return slot < LUMINA_SHADOW_CONSTANTS.shadowedPointCount ? pointVisibility(slot, position, normal) : 1.0;
}

float shadowVisibility(DeferredLight light, float3 position, float3 normal) {
    return shadowVisibilityOnPlane(light, position, normal, normal, false);
}

#endif
