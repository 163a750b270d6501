#ifndef LUMINA_SCENE_SHARED_H
#define LUMINA_SCENE_SHARED_H
// GPU layout of the scene as gi/gpu_scene/ uploads it, read by every renderer: vertices,
// instances, materials and per-draw constants. One vertex buffer and one index buffer hold
// every mesh; indices are absolute (the mesh's base vertex is baked in), so SV_VertexID is
// the same on Vulkan and D3D12 without a base-vertex offset.
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

#define LUMINA_NO_TEXTURE_LAYER 0xFFFFFFFFu
#define LUMINA_MATERIAL_DOUBLE_SIDED 1u

struct GpuVertex {
    float4 positionU; // xyz: object-space position; w: texture u
    float4 normalV;   // xyz: object-space unit normal; w: texture v
};

// Rows of the 3x4 object-to-world matrix, and of the normal matrix (inverse transpose).
struct GpuInstance {
    float4 objectToWorld[3];
    float4 normalToWorld[3];
    uint4 info; // x: mesh index; y: 1 when the transform mirrors (flips winding); zw: unused
};

// Shading is diffuse: albedo = baseColor.rgb x base-colour texture. Emission is radiance.
struct GpuMaterial {
    float4 baseColor;
    float4 emission; // rgb: radiance (emissive factor x strength); a: unused
    uint4 textures;  // x: base-colour layer; y: emission layer (LUMINA_NO_TEXTURE_LAYER: none);
                     // z: flags (LUMINA_MATERIAL_DOUBLE_SIDED); w: unused
};

// Push constants of one draw: which instance and material it shades.
struct GpuDrawConstants {
    uint instance;
    uint material;
    uint pad0;
    uint pad1;
};

LUMINA_STATIC_ASSERT_SIZE(GpuVertex, 32);
LUMINA_STATIC_ASSERT_SIZE(GpuInstance, 112);
LUMINA_STATIC_ASSERT_SIZE(GpuMaterial, 48);
LUMINA_STATIC_ASSERT_SIZE(GpuDrawConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
