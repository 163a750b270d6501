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
    float2 scale;     // clip = pixel * scale + translate (y down in pixels, up in clip space)
    float2 translate;
    // The first vertex of the draw list. Added in the shader, not as the draw's vertex offset:
    // SV_VertexID includes that offset on Vulkan and not on D3D12.
    uint vertexBase;
    uint pad0;
    uint pad1;
    uint pad2;
};
LUMINA_STATIC_ASSERT_SIZE(UiConstants, 32);
LUMINA_STATIC_ASSERT_OFFSET(UiConstants, translate, 8);
LUMINA_STATIC_ASSERT_OFFSET(UiConstants, vertexBase, 16);

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
    uint2 size;  // of the output, in pixels
    uint mode;   // LUMINA_VISUALISE_*
    uint layer;  // source array layer
    float rangeLo; // LUMINA_VISUALISE_SCALAR: the value shown black
    float rangeHi; //   and the value shown white
    float exposureScale; // LUMINA_VISUALISE_RADIANCE
    float rangePadding;
    // Probe buffers.
    uint2 probeGrid;      // probes across and down
    uint entriesPerProbe;
    uint tileWidth;       // entries across a probe's tile in the image
    // Slice views.
    uint sliceAxis; // LUMINA_VISUALISE_AXIS_*
    uint sdfCascade;
    uint sliceDims; // voxels per axis of the volume
    uint slicePadding;
    float3 sliceMin;     // the world box the image spans
    float slicePosition; // of the plane along the axis
    float3 sliceMax;     // the box's far corner
    float sliceMaxPadding;
};
LUMINA_STATIC_ASSERT_SIZE(VisualiseConstants, 96);
LUMINA_STATIC_ASSERT_OFFSET(VisualiseConstants, rangeLo, 16);
LUMINA_STATIC_ASSERT_OFFSET(VisualiseConstants, probeGrid, 32);
LUMINA_STATIC_ASSERT_OFFSET(VisualiseConstants, sliceAxis, 48);
LUMINA_STATIC_ASSERT_OFFSET(VisualiseConstants, sliceMin, 64);
LUMINA_STATIC_ASSERT_OFFSET(VisualiseConstants, sliceMax, 80);

LUMINA_GPU_NAMESPACE_END

#endif
