// lumina-kernel: cs main
// One camera ray per pixel (cameraRayDirection, camera_shared.h) traced through the scene's
// SDFs: the normal view of `lumina sdf --normals-png`, the golden images, and the trace
// throughput benchmark. Writes, per pixel, the world normal mapped to [0, 1] (black on a
// miss) and the hit distance.
#include "common/constants_shared.h"
#include "sdf/sdf_scene_bindings.hlsli"
#include "sdf/sdf_scene_trace_shared.h"

LUMINA_PUSH_CONSTANTS(SdfCameraTraceConstants, gConstants);
ConstantBuffer<SdfCameraView> gView : register(b1);
RWStructuredBuffer<float4> gPixels : register(u0); // rgb: 0.5 * normal + 0.5, 0 on a miss; a: t

[numthreads(LUMINA_SCREEN_GROUP_SIZE, LUMINA_SCREEN_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gConstants.width || id.y >= gConstants.height) {
        return;
    }
    float3 origin = cameraPosition(gView.camera);
    float3 direction = cameraRayDirection(gView.camera, float2(id.xy) + 0.5f);
    SdfHit hit;
    if (gConstants.mode == LUMINA_SDF_TRACE_NEAR_FIELD) {
        hit = sdfTraceNearField(origin, direction, 0.0f, gConstants.params);
    } else if (gConstants.mode == LUMINA_SDF_TRACE_FAR_FIELD) {
        hit = sdfTraceGlobal(origin, direction, 0.0f, gConstants.params);
    } else {
        hit = sdfConeTraceGlobal(origin, direction, 0.0f, gConstants.tanHalfAngle, gConstants.params);
    }
    float3 colour = sdfIsMiss(hit) ? float3(0.0f, 0.0f, 0.0f) : 0.5f * hit.normalAndCoverage.xyz + 0.5f;
    gPixels[id.y * gConstants.width + id.x] = float4(colour, hit.positionAndT.w);
}
