// lumina-kernel: cs main
// Test kernel for GPU SDF sampling and sphere tracing (the GPU twin of
// tests/sdf/sdf_trace_test.cpp): one thread per ray, traced through one volume of the atlas.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "common/bvh_shared.h"
#include "common/sdf_shared.h"
#include "sdf/sdf_test_shared.h"

LUMINA_PUSH_CONSTANTS(SdfTraceTestConstants, gConstants);

Texture3D<float> gSdfAtlas : register(t0);
StructuredBuffer<SdfVolumeDesc> gVolumes : register(t1);
StructuredBuffer<BvhRay> gRays : register(t2); // mesh space, normalised directions
SamplerState gLinearClamp : register(s0);
RWStructuredBuffer<float4> gHits
    : register(u0); // x: t; y: asfloat(hit); z: asfloat(steps); w: distance at the origin

#define LUMINA_SDF_ATLAS gSdfAtlas
#define LUMINA_SDF_SAMPLER gLinearClamp
#include "common/sdf_sampling.hlsli"

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id
                                 : SV_DispatchThreadID) {
    if (id.x >= gConstants.rayCount) {
        return;
    }
    BvhRay ray = gRays[id.x];
    SdfVolumeDesc desc = gVolumes[gConstants.volume];
    float3 invAtlasDims = gConstants.invAtlasDims.xyz;
    SdfTraceHit hit = sdfTraceVolume(desc, invAtlasDims, ray.originAndTMin.xyz, ray.directionAndTMax.xyz,
                                     ray.directionAndTMax.w);
    float atOrigin = sdfSampleVolume(desc, invAtlasDims, ray.originAndTMin.xyz);
    gHits[id.x] = float4(hit.t, asfloat(hit.hit), asfloat(hit.steps), atOrigin);
}
