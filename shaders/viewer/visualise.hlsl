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
#include "viewer/visualise_common.hlsli"

Texture2D<float4> gSource : register(t0);
Texture2DArray<float4> gSourceArray : register(t1);
Texture2D<uint4> gSourceUint : register(t2);
StructuredBuffer<float4> gProbeTexels : register(t3);
StructuredBuffer<float> gProbeScalars : register(t4);

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        gOutput[id.xy] = float4(display(gSource.Load(int3(id.xy, 0))), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void arrayLayer(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        const float4 value = gSourceArray.Load(int4(id.xy, gVisualise.layer, 0));
        gOutput[id.xy] = float4(display(value), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void uintTexture(uint3 id : SV_DispatchThreadID) {
    if (!outside(id.xy)) {
        gOutput[id.xy] = float4(idColor(gSourceUint.Load(int3(id.xy, 0)).x), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void probeMap(uint3 id : SV_DispatchThreadID) {
    uint probe, entry;
    if (probeEntry(id.xy, probe, entry)) {
        gOutput[id.xy] = float4(display(gProbeTexels[probe * gVisualise.entriesPerProbe + entry]), 1.0);
    }
}

[numthreads(LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE, 1)]
void probeTable(uint3 id : SV_DispatchThreadID) {
    uint probe, entry;
    if (probeEntry(id.xy, probe, entry)) {
        gOutput[id.xy] = float4(display(gProbeScalars[probe * gVisualise.entriesPerProbe + entry].xxxx), 1.0);
    }
}
