// lumina-kernel: cs main
// DDGI distance blend: each interior texel of a probe's 16 x 16 octahedral visibility tile keeps
// the mean distance to the surfaces around its direction d and the mean squared distance (for the
// Chebyshev test of ddgi_sample), each ray weighted by max(0, d.w)^sharpness, blended with the
// hysteresis. Distances are in the volume's unit (its largest spacing), so RG16F holds them in
// any scene; a back-face hit counts at a fifth of its distance (the probe is about to be moved or
// switched off: points behind that face must not read it), a miss at the max trace distance.
// Border copied. Inactive probes are left as they are.
#include "ddgi/ddgi_common.hlsli"

StructuredBuffer<DdgiProbe> gProbes : register(t0);
StructuredBuffer<float4> gRayData : register(t1);
LUMINA_UAV_FORMAT(rg16f) RWTexture2D<float2> gDistance : register(u0);

#include "ddgi/ddgi_blend_common.hlsli"

#define N LUMINA_DDGI_DISTANCE_SIZE
#define LUMINA_DDGI_BACKFACE_DISTANCE_SCALE 0.2
groupshared float2 gsTexel[N * N];

[numthreads(LUMINA_DDGI_DISTANCE_SIZE, LUMINA_DDGI_DISTANCE_SIZE, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    BlendTexel texel;
    if (!beginBlend(group.x, t, N, texel)) {
        return;
    }
    const DdgiVolumeInfo volume = gDdgi.volumes[texel.ref.volume];
    const float unit = volume.distanceUnit;
    const float3 d = texel.direction;
    float2 sum = float2(0.0, 0.0);
    float weight = 0.0;
    for (uint r = 0u; r < blendedRayCount(); ++r) {
        const float w = pow(max(0.0, dot(d, gsRayDirection[r].xyz)), gDdgi.distanceSharpness);
        const float signedDistance = gsRayData[r].a;
        const float distance =
            (signedDistance < 0.0 ? -LUMINA_DDGI_BACKFACE_DISTANCE_SCALE * signedDistance : signedDistance) /
            unit;
        sum += w * float2(distance, distance * distance);
        weight += w;
    }
    const uint2 tile = ddgiTileOrigin(volume, texel.ref.local, LUMINA_DDGI_DISTANCE_TILE);
    const uint2 at = tile + 1u + texel.local;
    const float2 previous = gDistance[at];
    const float hysteresis = blendHysteresis();
    // A fresh probe's stored texels are whatever the atlas held (NaN included): not read at all.
    const float2 fresh = weight > 0.0 ? sum / weight : float2(0.0, 0.0);
    float2 result = hysteresis > 0.0 ? lerp(fresh, previous, hysteresis) : fresh;
    result = ddgiSanitise(float3(result, 0.0)).xy;
    gDistance[at] = result;
    gsTexel[t] = result;
    GroupMemoryBarrierWithGroupSync();
    uint2 bordered;
    uint interior;
    if (borderTexel(t, N, bordered, interior)) {
        gDistance[tile + bordered] = gsTexel[interior];
    }
}
