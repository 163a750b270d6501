#ifndef LUMINA_VIEWER_SHARED_H
#define LUMINA_VIEWER_SHARED_H
// Push constants of the viewer's two kernels (app/viewer): the UI pipeline that draws Dear
// ImGui's triangles and the frame itself, and the visualise kernel that turns any intermediate
// buffer into a display image. (Include guard, not #pragma once: glslang ignores the pragma.)
#include "../common/shared_types.h"
#include "../common/constants_shared.h"

LUMINA_GPU_NAMESPACE_BEGIN

// ImGui's vertex as ImDrawVert lays it out: float2 position, float2 uv, RGBA8 colour (20 bytes,
// read from a ByteAddressBuffer: a structured buffer's stride would differ between std430 and D3D).
#define LUMINA_UI_VERTEX_BYTES 20

struct UiConstants {
    float4 scaleTranslate; // clip = pixel * xy + zw (y down in pixels, up in clip space)
    // x: the first vertex of the draw list. Added in the shader, not as the draw's vertex offset:
    // SV_VertexID includes that offset on Vulkan and not on D3D12.
    uint4 vertexBase;
};
LUMINA_STATIC_ASSERT_SIZE(UiConstants, 32);

// How visualise maps a texel to a colour.
#define LUMINA_VISUALISE_RADIANCE 0u // linear radiance: exposure, tonemap, sRGB (the composite's curve)
#define LUMINA_VISUALISE_COLOR 1u    // already in [0, 1] (albedo, display images): shown as it is
#define LUMINA_VISUALISE_NORMAL 2u   // unit vectors: n / 2 + 1/2
#define LUMINA_VISUALISE_SCALAR 3u   // the first channel, (v - lo) / (hi - lo) as grey
#define LUMINA_VISUALISE_ALPHA 4u    // the alpha channel as grey
#define LUMINA_VISUALISE_ID 5u       // the first channel as an integer id: a colour per id

#define LUMINA_VISUALISE_GROUP_SIZE LUMINA_SCREEN_GROUP_SIZE

// Slice views (the global SDF, the voxel lighting) cut the volume at a world position along
// one axis; the image spans the other two axes, the next one across and the one after up
// (x: z across, y up; y: x across, z up; z: x across, y up).
#define LUMINA_VISUALISE_AXIS_X 0u
#define LUMINA_VISUALISE_AXIS_Y 1u
#define LUMINA_VISUALISE_AXIS_Z 2u

struct VisualiseConstants {
    uint4 sizeModeLayer;  // output width, height; mode; source array layer
    float4 rangeExposure; // scalar lo, hi; exposure scale (radiance); unused
    uint4 probeGrid;      // probe buffers: grid width, height; entries per probe; tile width
    uint4 slice;          // slice views: axis; SDF cascade; voxels per axis of the volume; 0
    float4 sliceMin;      // slice views: xyz the world box the image spans; w the plane's position
    float4 sliceMax;      //   along the axis; xyz the box's far corner; w 0
};
LUMINA_STATIC_ASSERT_SIZE(VisualiseConstants, 96);

LUMINA_GPU_NAMESPACE_END

#endif
