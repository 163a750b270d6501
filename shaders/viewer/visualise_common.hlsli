#ifndef LUMINA_VISUALISE_COMMON_HLSLI
#define LUMINA_VISUALISE_COMMON_HLSLI
// What every debug-view kernel of the viewer shares (app/viewer/buffer_views.cpp): the
// constants, the display image it writes (u0: RGBA8, sRGB-encoded like the composite's output),
// and the mapping of a value to a colour by mode.
#include "common/bindings.hlsli"
#include "common/tonemap_shared.h"
#include "viewer/viewer_shared.h"

LUMINA_PUSH_CONSTANTS(VisualiseConstants, gVisualise);
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
    const uint mode = gVisualise.mode;
    if (mode == LUMINA_VISUALISE_RADIANCE) {
        return tonemapToDisplay3(value.rgb, gVisualise.exposureScale);
    }
    if (mode == LUMINA_VISUALISE_NORMAL) {
        return saturate(value.xyz * 0.5 + 0.5);
    }
    if (mode == LUMINA_VISUALISE_SCALAR || mode == LUMINA_VISUALISE_ALPHA) {
        const float v = mode == LUMINA_VISUALISE_SCALAR ? value.x : value.w;
        const float lo = gVisualise.rangeLo;
        const float hi = gVisualise.rangeHi;
        return saturate((v - lo) / max(hi - lo, 1e-20)).xxx;
    }
    if (mode == LUMINA_VISUALISE_ID) {
        return idColor(uint(value.x));
    }
    return saturate(value.rgb);
}

bool outside(uint2 id) {
    return id.x >= gVisualise.size.x || id.y >= gVisualise.size.y;
}

// Probe p = (px, py) owns a tile tileWidth entries wide at (px tileWidth, py tileHeight); entry i of
// it, at (i % tileWidth, i / tileWidth) in the tile, is element p perProbe + i of the buffer (the
// layout of gi/screen_probes/screen_probe_readback.cpp's images). False outside the image, and for
// the tile's texels past the last entry, which it paints black.
bool probeEntry(uint2 id, out uint probe, out uint entry) {
    probe = 0;
    entry = 0;
    if (outside(id)) {
        return false;
    }
    const uint perProbe = gVisualise.entriesPerProbe;
    const uint tileWidth = gVisualise.tileWidth;
    const uint tileHeight = (perProbe + tileWidth - 1u) / tileWidth;
    const uint2 tile = uint2(id.x / tileWidth, id.y / tileHeight);
    probe = tile.y * gVisualise.probeGrid.x + tile.x;
    entry = (id.y % tileHeight) * tileWidth + id.x % tileWidth;
    if (entry >= perProbe) {
        gOutput[id] = float4(0.0, 0.0, 0.0, 1.0);
        return false;
    }
    return true;
}

// Slice views: the world point at uv (0..1 across and down the image) of the plane through
// sliceMin.w across the axis, over the box [sliceMin, sliceMax]; see LUMINA_VISUALISE_AXIS_X.
float3 slicePoint(float2 uv) {
    const uint axis = gVisualise.sliceAxis;
    const uint across = axis == LUMINA_VISUALISE_AXIS_X ? 2u : 0u;
    const uint up = axis == LUMINA_VISUALISE_AXIS_Y ? 2u : 1u;
    const float onAxis = gVisualise.slicePosition;
    const float onAcross = lerp(gVisualise.sliceMin[across], gVisualise.sliceMax[across], uv.x);
    const float onUp = lerp(gVisualise.sliceMax[up], gVisualise.sliceMin[up], uv.y); // +up at the top
    // Built by selection, not by storing to p[axis]: vkd3d's DXBC compiler cannot store to a
    // vector component chosen at run time.
    return float3(axis == 0u ? onAxis : (across == 0u ? onAcross : onUp),
                  axis == 1u ? onAxis : (across == 1u ? onAcross : onUp),
                  axis == 2u ? onAxis : (across == 2u ? onAcross : onUp));
}

#endif
