// lumina-kernel: cs main
// lumina-kernel: cs arrayLayer
// lumina-kernel: cs uintTexture
// lumina-kernel: cs probeMap
// lumina-kernel: cs probeTable
// The viewer's debug views (app/viewer/buffer_views.cpp): any intermediate buffer of the frame
// as a display image (RGBA8, sRGB-encoded like the composite's output), one entry point per
// kind of source: a 2D float texture (GBuffer targets, depth, shadow map, direct light, the
// indirect term, atlas layers), one layer of a 2D array, a 2D uint texture (ids), and the
// screen probes' per-probe buffers of float4 or float entries (radiance, rays, PDFs), tiled.
#include "common/bindings.hlsli"
#include "common/tonemap_shared.h"
#include "viewer/viewer_shared.h"

LUMINA_PUSH_CONSTANTS(VisualiseConstants, gVisualise);
Texture2D<float4> gSource : register(t0);
Texture2DArray<float4> gSourceArray : register(t1);
Texture2D<uint4> gSourceUint : register(t2);
StructuredBuffer<float4> gProbeTexels : register(t3);
StructuredBuffer<float> gProbeScalars : register(t4);
LUMINA_UAV_FORMAT(rgba8) RWTexture2D<float4> gOutput : register(u0);

// A colour per integer id (a bit-mixing hash, so that neighbouring ids differ); id ~0u: black.
float3 idColor(uint id) {
    if (id == 0xFFFFFFFFu) {
        return float3(0.0, 0.0, 0.0);
    }
    uint h = id * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float3(h & 0xFFu, (h >> 8) & 0xFFu, (h >> 16) & 0xFFu) / 255.0 * 0.8 + 0.2;
}

float3 display(float4 value) {
    const uint mode = gVisualise.sizeModeLayer.z;
    if (mode == LUMINA_VISUALISE_RADIANCE) {
        return tonemapToDisplay3(value.rgb, gVisualise.rangeExposure.z);
    }
    if (mode == LUMINA_VISUALISE_NORMAL) {
        return saturate(value.xyz * 0.5 + 0.5);
    }
    if (mode == LUMINA_VISUALISE_SCALAR || mode == LUMINA_VISUALISE_ALPHA) {
        const float v = mode == LUMINA_VISUALISE_SCALAR ? value.x : value.w;
        const float lo = gVisualise.rangeExposure.x;
        const float hi = gVisualise.rangeExposure.y;
        return saturate((v - lo) / max(hi - lo, 1e-20)).xxx;
    }
    if (mode == LUMINA_VISUALISE_ID) {
        return idColor(uint(value.x));
    }
    return saturate(value.rgb);
}

bool outside(uint2 id) {
    return id.x >= gVisualise.sizeModeLayer.x || id.y >= gVisualise.sizeModeLayer.y;
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        gOutput[id.xy] = float4(display(gSource.Load(int3(id.xy, 0))), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void arrayLayer(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        const float4 value = gSourceArray.Load(int4(id.xy, gVisualise.sizeModeLayer.w, 0));
        gOutput[id.xy] = float4(display(value), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void uintTexture(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        gOutput[id.xy] = float4(idColor(gSourceUint.Load(int3(id.xy, 0)).x), 1.0);
    }
}

// Probe p = (px, py) owns a tile tileWidth entries wide at (px tileWidth, py tileHeight); entry i of
// it, at (i % tileWidth, i / tileWidth) in the tile, is element p perProbe + i of the buffer (the
// layout of gi/screen_probes/screen_probe_readback.cpp's images). False outside the image, and for
// the tile's texels past the last entry, which it paints black.
bool probeEntry(uint2 id, out uint index) {
    index = 0;
    if (outside(id)) {
        return false;
    }
    const uint perProbe = gVisualise.probeGrid.z;
    const uint tileWidth = gVisualise.probeGrid.w;
    const uint tileHeight = (perProbe + tileWidth - 1u) / tileWidth;
    const uint2 probe = uint2(id.x / tileWidth, id.y / tileHeight);
    const uint entry = (id.y % tileHeight) * tileWidth + id.x % tileWidth;
    index = (probe.y * gVisualise.probeGrid.x + probe.x) * perProbe + entry;
    if (entry >= perProbe) {
        gOutput[id] = float4(0.0, 0.0, 0.0, 1.0);
        return false;
    }
    return true;
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void probeMap(uint3 id : SV_DispatchThreadID) {
    uint index;
    if (probeEntry(id.xy, index)) {
        gOutput[id.xy] = float4(display(gProbeTexels[index]), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void probeTable(uint3 id : SV_DispatchThreadID) {
    uint index;
    if (probeEntry(id.xy, index)) {
        gOutput[id.xy] = float4(display(gProbeScalars[index].xxxx), 1.0);
    }
}
