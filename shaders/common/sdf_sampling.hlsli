#ifndef LUMINA_SDF_SAMPLING_HLSLI
#define LUMINA_SDF_SAMPLING_HLSLI
// Sampling and sphere tracing of one mesh SDF in the atlas (layout: sdf_shared.h), the GPU
// twin of sampleSdf() (gi/sdf/sdf_atlas.cpp) and traceSdf() (gi/sdf/sdf_trace.cpp); the CPU
// versions are the reference the GPU tests compare against. Hardware trilinear filtering
// has 8-bit weights, so expect differences of a few thousandths of a voxel.
//
// The includer names the atlas and a linear, clamp-to-edge sampler first:
//
//   Texture3D<float> gSdfAtlas : register(t0);
//   SamplerState gLinearClamp : register(s0);
//   #define LUMINA_SDF_ATLAS gSdfAtlas
//   #define LUMINA_SDF_SAMPLER gLinearClamp
//   #include "common/sdf_sampling.hlsli"
#include "ray_box.hlsli"
#include "sdf_shared.h"

#if !defined(LUMINA_SDF_ATLAS) || !defined(LUMINA_SDF_SAMPLER)
#error "define LUMINA_SDF_ATLAS and LUMINA_SDF_SAMPLER before including sdf_sampling.hlsli"
#endif

// Hit when the sampled distance falls below this many voxels (SdfTraceSettings' default).
#define LUMINA_SDF_HIT_THRESHOLD_VOXELS 0.1f
#define LUMINA_SDF_MAX_STEPS 128u

// Signed distance in mesh units at a mesh-space point. Outside the volume box: a lower bound,
// sqrt(d^2 + s^2) with d the distance to the box and s the sample at the nearest box point.
float sdfSampleVolume(SdfVolumeDesc desc, float3 invAtlasDims, float3 p) {
    float3 boxMin = desc.volumeMinAndVoxelSize.xyz;
    float3 boxMax = desc.volumeMaxAndInvVoxelSize.xyz;
    float3 inBox = clamp(p, boxMin, boxMax);
    // Local voxel coordinate with texel centres at i + 0.5, kept half a voxel inside so the
    // filter never reads a neighbouring volume.
    float3 local = clamp((inBox - boxMin) * desc.volumeMaxAndInvVoxelSize.w, float3(0.5f, 0.5f, 0.5f),
                         float3(desc.dims.xyz) - 0.5f);
    float3 uvw = (float3(desc.atlasOffset.xyz) + local) * invAtlasDims;
    float stored = LUMINA_SDF_ATLAS.SampleLevel(LUMINA_SDF_SAMPLER, uvw, 0.0f) * desc.volumeMinAndVoxelSize.w;
    float3 outside = p - inBox;
    float outsideSquared = dot(outside, outside);
    if (outsideSquared > 0.0f) {
        float atBox = max(stored, 0.0f);
        return sqrt(outsideSquared + atBox * atBox);
    }
    return stored;
}

struct SdfTraceHit {
    uint hit; // 1 when the surface was reached
    float t;  // along the normalised direction; the ray's tMax on a miss
    uint steps;
};

// Sphere tracing in mesh space; `direction` normalised. Starting inside the surface is a hit
// at the volume entry.
SdfTraceHit sdfTraceVolume(SdfVolumeDesc desc, float3 invAtlasDims, float3 origin, float3 direction,
                           float tMax) {
    SdfTraceHit result;
    result.hit = 0u;
    result.t = tMax;
    result.steps = 0u;
    float2 range = boxEntryExit(origin, safeReciprocal3(direction), desc.volumeMinAndVoxelSize.xyz,
                                desc.volumeMaxAndInvVoxelSize.xyz);
    float t = max(range.x, 0.0f);
    float tExit = min(range.y, tMax);
    if (!(t <= tExit)) {
        return result;
    }
    float threshold = LUMINA_SDF_HIT_THRESHOLD_VOXELS * desc.volumeMinAndVoxelSize.w;
    for (uint step = 0u; step < LUMINA_SDF_MAX_STEPS; ++step) {
        result.steps = step + 1u;
        float d = sdfSampleVolume(desc, invAtlasDims, origin + t * direction);
        if (d < threshold) {
            result.hit = 1u;
            result.t = t;
            return result;
        }
        t += d;
        if (t > tExit) {
            return result;
        }
    }
    return result;
}

#endif
