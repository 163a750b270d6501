// lumina-kernel: cs main
// The viewer's global SDF slice (app/viewer/gi_views.cpp): one cascade of the global SDF the
// renderer composed this frame, cut by a plane across one axis, colour-mapped as `lumina sdf
// --slice-png` maps its slice (gi/sdf/sdf_views.h): magma over [-maxDistance, maxDistance], dark
// inside and bright far outside, white within half a voxel of a surface, a darker line every two
// voxels of distance (none where the field is truncated). Each texel samples the cascade
// trilinearly (sdfSampleCascade), so the image is finer than the voxels and the lines stay smooth.
#include "sdf/sdf_scene_bindings.hlsli"
#include "viewer/visualise_common.hlsli"

// Level-set line every this many voxels of distance, as thick as this fraction of the spacing.
#define LUMINA_SLICE_LEVEL_SPACING_VOXELS 2.0
#define LUMINA_SLICE_LEVEL_LINE 0.125
// matplotlib 3.6 magma at t = 0, 1/8, ..., 1 (display-encoded sRGB), the stops of
// gi/image/colormap.cpp.
static const float3 kMagma[9] = {float3(0.0015, 0.0005, 0.0139), float3(0.1131, 0.0655, 0.2768),
                                 float3(0.3167, 0.0717, 0.4854), float3(0.5128, 0.1482, 0.5076),
                                 float3(0.7164, 0.2150, 0.4753), float3(0.9043, 0.3196, 0.3881),
                                 float3(0.9867, 0.5356, 0.3822), float3(0.9969, 0.7696, 0.5349),
                                 float3(0.9871, 0.9914, 0.7495)};

float3 magma(float t) {
    const float u = saturate(t) * 8.0;
    const uint i = min(uint(u), 7u);
    return lerp(kMagma[i], kMagma[i + 1u], u - float(i));
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (outside(id.xy)) {
        return;
    }
    const uint c = min(gVisualise.sdfCascade, sdfGlobalCascadeCount() - 1u);
    const SdfGlobalCascade cascade = gSdfScene.cascades[c];
    const float voxel = cascade.voxelSize;
    const float maxDistance = cascade.maxDistance;
    const float2 uv = (float2(id.xy) + 0.5) / float2(gVisualise.size);
    const float d = sdfSampleCascade(c, slicePoint(uv));
    float3 color = magma(0.5 + 0.5 * d / maxDistance);
    const float inVoxels = abs(d) / voxel;
    if (inVoxels < 0.5) {
        color = float3(1.0, 1.0, 1.0);
    } else if (abs(d) < maxDistance - 0.5 * voxel &&
               fmod(inVoxels, LUMINA_SLICE_LEVEL_SPACING_VOXELS) <
                   LUMINA_SLICE_LEVEL_LINE * LUMINA_SLICE_LEVEL_SPACING_VOXELS) {
        // No lines where the distance is truncated: the field is flat there.
        color *= 0.6;
    }
    gOutput[id.xy] = float4(color, 1.0);
}
