// lumina-kernel: cs main
// Traces a buffer of world-space rays through the scene's SDFs with one part of the tracing
// library (near field, far field or cone), one thread per ray: the kernel of the GPU tests
// that hold the tracers against BVH ray casts and the CPU references.
#include "common/constants_shared.h"
#include "sdf/sdf_scene_bindings.hlsli"
#include "sdf/sdf_scene_trace_shared.h"

LUMINA_PUSH_CONSTANTS(SdfTraceRaysConstants, gConstants);
StructuredBuffer<BvhRay> gRays : register(t6); // unit directions; tMin in originAndTMin.w
RWStructuredBuffer<SdfHit> gHits : register(u0);

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gConstants.rayCount) {
        return;
    }
    BvhRay ray = gRays[id.x];
    float3 origin = ray.originAndTMin.xyz;
    float3 direction = ray.directionAndTMax.xyz;
    float tMin = ray.originAndTMin.w;
    SdfHit hit;
    if (gConstants.mode == LUMINA_SDF_TRACE_NEAR_FIELD) {
        hit = sdfTraceNearField(origin, direction, tMin, gConstants.params);
    } else if (gConstants.mode == LUMINA_SDF_TRACE_FAR_FIELD) {
        hit = sdfTraceGlobal(origin, direction, tMin, gConstants.params);
    } else {
        hit = sdfConeTraceGlobal(origin, direction, tMin, gConstants.tanHalfAngle, gConstants.params);
    }
    gHits[id.x] = hit;
}
