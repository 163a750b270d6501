// lumina-kernel: cs main
// Pass 12, screen temporal filter: the gathered irradiance blended with last frame's result at
// the pixel this surface point was seen at then (reprojected through the previous camera). The
// history is kept only where that pixel held the same surface (its stored world position within
// historyPlaneTolerance x view depth); it is clamped to the 3x3 neighbourhood of this frame's gather so that
// moving light does not smear, and blended with weight max(screenHistoryBlend, 1 / (frames + 1)) for
// the new frame, so a fresh pixel converges like a running mean. Disoccluded pixels restart
// from the current frame. Non-finite values are never written to history.
// One thread per pixel; writes the filtered irradiance and this frame's positions (the next
// frame's disocclusion test).
#include "screen_probes/screen_probe_common.hlsli"

Texture2D<float4> gGather : register(t0);
Texture2D<float4> gPosition : register(t1);          // GBuffer: world position, view depth
Texture2D<float4> gPreviousIrradiance : register(t2); // this pass's output last frame
Texture2D<float4> gPreviousPosition : register(t3);
// rgb: irradiance; a: frames accumulated.
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gIrradiance : register(u0);
LUMINA_UAV_FORMAT(rgba32f) RWTexture2D<float4> gPositionHistory : register(u1);

// Frame count saturates here (the blend is screenHistoryBlend from then on; half floats hold it exactly).
#define LUMINA_SP_MAX_HISTORY_FRAMES 255.0

[numthreads(LUMINA_SP_SCREEN_GROUP, LUMINA_SP_SCREEN_GROUP, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gSp.imageSize.x || id.y >= gSp.imageSize.y) {
        return;
    }
    const float4 position = gPosition.Load(int3(id.xy, 0));
    gPositionHistory[id.xy] = position;
    const float4 current = gGather.Load(int3(id.xy, 0));
    if (position.w <= 0.0 || current.a <= 0.0) {
        gIrradiance[id.xy] = float4(0.0, 0.0, 0.0, 0.0);
        return;
    }
    float3 lo = current.rgb;
    float3 hi = current.rgb;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int2 at = clamp(int2(id.xy) + int2(dx, dy), int2(0, 0), int2(gSp.imageSize) - 1);
            const float4 v = gGather.Load(int3(at, 0));
            if (v.a > 0.0) {
                lo = min(lo, v.rgb);
                hi = max(hi, v.rgb);
            }
        }
    }
    float4 history = float4(0.0, 0.0, 0.0, 0.0);
    float2 pixel;
    if (hasFlag(LUMINA_SP_FLAG_SCREEN_HISTORY) && previousPixel(position.xyz, pixel)) {
        const int3 at = int3(min(uint2(pixel), gSp.imageSize - 1u), 0);
        const float4 old = gPreviousPosition.Load(at);
        if (old.w > 0.0 && length(old.xyz - position.xyz) <= gSp.historyPlaneTolerance * position.w) {
            history = gPreviousIrradiance.Load(at);
            // Fewer frames of history where the scene changed (0: none).
            history.a = floor(history.a * historyKeep(position.xyz));
        }
    }
    float4 result = float4(current.rgb, 1.0);
    if (history.a > 0.0 && allFinite3(history.rgb)) {
        const float blend = max(gSp.screenHistoryBlend, 1.0 / (history.a + 1.0));
        result = float4(lerp(clamp(history.rgb, lo, hi), current.rgb, blend),
                        min(history.a + 1.0, LUMINA_SP_MAX_HISTORY_FRAMES));
    }
    if (!allFinite3(result.rgb)) {
        result = float4(0.0, 0.0, 0.0, 0.0);
    }
    gIrradiance[id.xy] = result;
}
