// lumina-kernel: cs radiosityProbes
// lumina-kernel: cs voxelSlice
// The viewer's views of the surface cache's lighting (app/viewer/gi_views.cpp):
//   radiosityProbes: the radiosity probes (one per 4x4 atlas texels, in the atlas's probe grid):
//                    irradiance of their L1 SH at their normal (what the integrate step gives
//                    their texels) in radiance mode, or their normal in normal mode; black where
//                    no probe sits on a surface.
//   voxelSlice:      a slice of the voxel lighting volume, its six faces (+x, +y, +z above -x,
//                    -y, -z) side by side, nearest voxel; rgb radiance where a face holds light
//                    (coverage above 0), dark grey where it is empty.
#include "viewer/visualise_common.hlsli"
#include "common/constants_shared.h"
#include "surface_cache/surface_cache_lighting_shared.h"

StructuredBuffer<RadiosityProbe> gProbes : register(t0);
Texture3D<float4> gVoxelLighting : register(t1); // LUMINA_VOXEL_FACES columns of slice.z voxels along x

// Empty voxel faces, told apart from faces that hold no light.
#define LUMINA_EMPTY_VOXEL 0.08

// Irradiance of L1 SH at normal n, as shaders/surface_cache/radiosity.hlsl integrates it.
float shL1Irradiance(float4 sh, float3 n) {
    return max(LUMINA_PI * LUMINA_SH_Y00 * sh.x + (2.0 * LUMINA_PI / 3.0) * LUMINA_SH_Y1 * dot(sh.yzw, n), 0.0);
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void radiosityProbes(uint3 id : SV_DispatchThreadID) {
    if (outside(id.xy)) {
        return;
    }
    const RadiosityProbe probe = gProbes[id.y * gVisualise.size.x + id.x];
    float3 color = float3(0.0, 0.0, 0.0);
    if (probe.normalAndTexel.w != 0.0) {
        const float3 n = normalize(probe.normalAndTexel.xyz);
        const float3 irradiance =
            float3(shL1Irradiance(probe.r, n), shL1Irradiance(probe.g, n), shL1Irradiance(probe.b, n));
        color = display(gVisualise.mode == LUMINA_VISUALISE_NORMAL ? float4(n, 1.0)
                                                                             : float4(irradiance, 1.0));
    }
    gOutput[id.xy] = float4(color, 1.0);
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void voxelSlice(uint3 id : SV_DispatchThreadID) {
    if (outside(id.xy)) {
        return;
    }
    // Three panes across (the axes), two down (the signs): face 2 axis + sign.
    const float2 panes = float2(3.0, 2.0);
    const float2 inImage = (float2(id.xy) + 0.5) / float2(gVisualise.size) * panes;
    const uint2 pane = min(uint2(inImage), uint2(2, 1));
    const uint face = 2u * pane.x + pane.y;
    const float3 p = slicePoint(inImage - float2(pane));
    const uint dims = gVisualise.sliceDims;
    const float3 box = gVisualise.sliceMax - gVisualise.sliceMin;
    const uint3 voxel = min(uint3(max((p - gVisualise.sliceMin) / box, 0.0) * float(dims)), dims - 1u);
    const float4 texel = gVoxelLighting.Load(int4(face * dims + voxel.x, voxel.y, voxel.z, 0));
    const float3 empty = float3(LUMINA_EMPTY_VOXEL, LUMINA_EMPTY_VOXEL, LUMINA_EMPTY_VOXEL);
    const float3 color = texel.a > 0.0 ? display(float4(texel.rgb, 1.0)) : empty;
    gOutput[id.xy] = float4(color, 1.0);
}
