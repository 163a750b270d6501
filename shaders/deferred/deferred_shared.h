#ifndef LUMINA_DEFERRED_SHARED_H
#define LUMINA_DEFERRED_SHARED_H
// Every constant and GPU struct the deferred renderer's kernels read (gi/deferred/ and
// shaders/deferred/), in one header for C++ and HLSL (docs/deferred.md).
#include "../common/camera_shared.h"
#include "../common/constants_shared.h"
#include "../common/lights_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

// Thread group edge of the full-screen compute passes (direct light, composite).
#define LUMINA_DEFERRED_GROUP_SIZE LUMINA_SCREEN_GROUP_SIZE

// Point and spot lights with a cube shadow map; any further ones light unshadowed.
#define LUMINA_MAX_SHADOWED_LIGHTS 4
#define LUMINA_CUBE_FACE_COUNT 6

// DeferredLight::shadowSlot of a light that casts no shadow (beyond the shadow-casting budget).
#define LUMINA_SHADOW_SLOT_NONE 0xFFFFFFFFu

// CompositeConstants::flags.
#define LUMINA_DEFERRED_FLAG_INDIRECT 1u // the composite adds indirect x albedo

// Shadow biases, in shadow-map texels of world size at the receiver (docs/deferred.md, "Shadows").
// The receiver is moved along its normal by the normal offset, then compared with a constant
// depth bias: 1.5 texels of normal offset keep surfaces lit at grazing angles free of acne across
// the 3x3 PCF footprint; the depth bias only absorbs rounding. Where the deferred direct light
// knows the plane of the surface's own triangles, the sun's taps are compared with that plane
// instead and the receiver is not moved (the offset lifted a floor point beside a wall above the
// wall's foot, and the sun reached it through the wall); the slope bias, a tenth of the plane's
// depth change per texel, covers planes taken across two facets of a curved mesh. Where the
// shading normal is the plane's own (within 0.8 degrees: a flat surface, no facets to cover) the
// depth bias is a fiftieth of a texel instead of a tenth, which let the sun through the bottom
// millimetres of a zero-thickness wall onto the floor row at its foot; on a curved mesh the
// smaller bias striped the engine's end caps. Only planes within 70 degrees of the sun (cosine
// 0.34): further, a texel's worth of error in the plane is several texels of depth, and city's
// facades lit at grazing angles showed acne.
#define LUMINA_SUN_NORMAL_OFFSET_TEXELS 1.5f
#define LUMINA_SUN_DEPTH_BIAS_TEXELS 0.1f
#define LUMINA_SUN_FLAT_DEPTH_BIAS_TEXELS 0.02f
#define LUMINA_SUN_FLAT_MIN_COSINE 0.9999f
#define LUMINA_SUN_SLOPE_BIAS 0.1f
#define LUMINA_SUN_PLANE_MIN_COSINE 0.34f
#define LUMINA_POINT_NORMAL_OFFSET_TEXELS 1.5f
#define LUMINA_POINT_DEPTH_BIAS_TEXELS 1.0f
// Near plane of the cube faces as a fraction of the shadow range: geometry closer to the
// light than this is clipped from its shadow map.
#define LUMINA_POINT_SHADOW_NEAR_FRACTION 1.0e-4f

// Frame-wide constants (register b0 of every deferred kernel).
struct DeferredFrameConstants {
    GpuCamera camera;
    uint lightCount;
    uint width; // of the image, in pixels
    uint height;
    uint pad0;
};
LUMINA_STATIC_ASSERT_SIZE(DeferredFrameConstants, 160);
LUMINA_STATIC_ASSERT_OFFSET(DeferredFrameConstants, lightCount, 144);

// A shadow-casting point or spot light (DeferredShadowConstants::pointLights).
struct ShadowedPointLight {
    float3 position; // world
    float range;     // shadow range: the cube maps store distance / range
};
LUMINA_STATIC_ASSERT_SIZE(ShadowedPointLight, 16);

// The one constant buffer of both shadow kinds (register b1): the sun's orthographic
// projection and the shadow-casting point and spot lights.
struct DeferredShadowConstants {
    // World to the sun's clip space: x right, y up, depth 0 nearest the sun, 1 farthest.
    float4 sunViewProjRows[4];
    float sunMapSize;        // texels per side; 0: no sun map
    float sunMapInvSize;     // 1 / sunMapSize
    float sunTexelWorld;     // world size of one texel
    float sunDepthRange;     // world distance depth 0..1 spans
    float pointFaceSize;     // cube face texels per side
    float pointFaceInvSize;  // 1 / pointFaceSize
    float pointNearFraction; // near plane of the faces, a fraction of the shadow range
    uint shadowedPointCount; // cubes in use
    ShadowedPointLight pointLights[LUMINA_MAX_SHADOWED_LIGHTS]; // one per cube
};
LUMINA_STATIC_ASSERT_SIZE(DeferredShadowConstants, 160);
LUMINA_STATIC_ASSERT_OFFSET(DeferredShadowConstants, sunMapSize, 64);
LUMINA_STATIC_ASSERT_OFFSET(DeferredShadowConstants, pointFaceSize, 80);
LUMINA_STATIC_ASSERT_OFFSET(DeferredShadowConstants, pointLights, 96);

// One light of the direct-light pass: the shared light model (lights_shared.h) and its shadow.
struct DeferredLight {
    GpuLight light;
    uint shadowSlot; // 0 = the sun map for a directional light, the cube index for point and spot
                     // lights, LUMINA_SHADOW_SLOT_NONE: unshadowed
    uint pad0;
    uint pad1;
    uint pad2;
};
LUMINA_STATIC_ASSERT_SIZE(DeferredLight, 80);
LUMINA_STATIC_ASSERT_OFFSET(DeferredLight, shadowSlot, 64);

// ---- GBuffer: visibility raster, then attribute resolve ----------------------------------
// The raster writes one R32_UINT per pixel (docs/deferred.md, "GBuffer"): 0 where no surface,
// else the id of the triangle drawn there plus LUMINA_GBUFFER_FRONT_FACE when the rasteriser
// saw its front face. Ids are numbered per draw: draw d's triangle t is firstId(d) + t, with
// firstId starting at 1, so an instanced mesh's triangles get one id per instance.
#define LUMINA_GBUFFER_FRONT_FACE 0x80000000u
#define LUMINA_GBUFFER_ID_MASK 0x7FFFFFFFu

// Push constants of one visibility draw.
struct GBufferVisibilityDrawConstants {
    uint instance;
    uint firstId; // the id of the draw's first triangle
    uint pad0;
    uint pad1;
};
LUMINA_STATIC_ASSERT_SIZE(GBufferVisibilityDrawConstants, 16);

// One draw as the resolve finds it from a triangle id; the table is sorted by firstId.
struct GBufferResolveDraw {
    uint firstId;
    uint firstIndex; // the draw's first index in the scene index buffer
    uint instance;
    uint material;
};
LUMINA_STATIC_ASSERT_SIZE(GBufferResolveDraw, 16);

// Resolve push constants.
struct GBufferResolveConstants {
    uint width;
    uint height;
    uint drawCount;
    uint pad0;
};
LUMINA_STATIC_ASSERT_SIZE(GBufferResolveConstants, 16);

// Push constants of one shadow draw.
struct ShadowDrawConstants {
    uint instance;
    uint layer; // cube array layer 6 x cube + face; 0 for the sun
    uint pad0;
    uint pad1;
};
LUMINA_STATIC_ASSERT_SIZE(ShadowDrawConstants, 16);

// Composite push constants.
struct CompositeConstants {
    uint width;
    uint height;
    uint flags;          // LUMINA_DEFERRED_FLAG_*
    float exposureScale; // 2^EV
    float indirectScale; // the indirect texture times this is the radiance-like term times albedo
    float pad0;
    float pad1;
    float pad2;
};
LUMINA_STATIC_ASSERT_SIZE(CompositeConstants, 32);

// ---- cube faces -------------------------------------------------------------------------
// The face convention of both APIs (Vulkan spec "Cube Map Face Selection", D3D the same):
// faces +X, -X, +Y, -Y, +Z, -Z; for direction d the face's major axis ma and its (sc, tc):
//   +X: ma  x, sc -z, tc -y      -X: ma -x, sc  z, tc -y
//   +Y: ma  y, sc  x, tc  z      -Y: ma -y, sc  x, tc -z
//   +Z: ma  z, sc  x, tc -y      -Z: ma -z, sc -x, tc -y
// u = (sc / ma + 1) / 2 runs along texel columns, v = (tc / ma + 1) / 2 down texel rows.
// The point-shadow pass renders each face with these same axes (cubeFaceClip), so the maps
// also read correctly as a TextureCubeArray (tests/deferred: PointShadowMapsFollowTheApiCubeConvention).
struct CubeFaceAxes {
    float3 major; // ma = dot(major, d)
    float3 s;     // sc = dot(s, d)
    float3 t;     // tc = dot(t, d)
};

LUMINA_INLINE CubeFaceAxes cubeFaceAxes(uint face) {
    CubeFaceAxes axes;
    if (face == 0u) {
        axes.major = float3(1, 0, 0);
        axes.s = float3(0, 0, -1);
        axes.t = float3(0, -1, 0);
    } else if (face == 1u) {
        axes.major = float3(-1, 0, 0);
        axes.s = float3(0, 0, 1);
        axes.t = float3(0, -1, 0);
    } else if (face == 2u) {
        axes.major = float3(0, 1, 0);
        axes.s = float3(1, 0, 0);
        axes.t = float3(0, 0, 1);
    } else if (face == 3u) {
        axes.major = float3(0, -1, 0);
        axes.s = float3(1, 0, 0);
        axes.t = float3(0, 0, -1);
    } else if (face == 4u) {
        axes.major = float3(0, 0, 1);
        axes.s = float3(1, 0, 0);
        axes.t = float3(0, -1, 0);
    } else {
        axes.major = float3(0, 0, -1);
        axes.s = float3(-1, 0, 0);
        axes.t = float3(0, -1, 0);
    }
    return axes;
}

// The face a direction falls on (ties go to x, then y, as the APIs do).
LUMINA_INLINE uint cubeFaceOf(float3 d) {
    const float3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) {
        return d.x >= 0.0f ? 0u : 1u;
    }
    if (a.y >= a.z) {
        return d.y >= 0.0f ? 2u : 3u;
    }
    return d.z >= 0.0f ? 4u : 5u;
}

// (u, v) in [0, 1] of direction d on `face`.
LUMINA_INLINE float2 cubeFaceUv(float3 d, uint face) {
    const CubeFaceAxes axes = cubeFaceAxes(face);
    const float ma = dot(axes.major, d);
    return float2(0.5f * (dot(axes.s, d) / ma + 1.0f), 0.5f * (dot(axes.t, d) / ma + 1.0f));
}

// Clip-space position of `offset` (point minus light position) on `face`: a 90-degree
// perspective whose depth is 0 at the near plane and 1 at the far plane; clip y is up, so
// row 0 (v = 0) is the top of the rendered face.
LUMINA_INLINE float4 cubeFaceClip(float3 offset, uint face, float nearPlane, float farPlane) {
    const CubeFaceAxes axes = cubeFaceAxes(face);
    const float ma = dot(axes.major, offset);
    const float depthScale = farPlane / (farPlane - nearPlane);
    return float4(dot(axes.s, offset), -dot(axes.t, offset), (ma - nearPlane) * depthScale, ma);
}

LUMINA_GPU_NAMESPACE_END

#endif
