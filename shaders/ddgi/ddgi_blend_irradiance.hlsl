// lumina-kernel: cs main
// DDGI irradiance blend: each interior texel of a probe's 8 x 8 octahedral irradiance tile folds
// this update's rays into the irradiance E arriving at a surface facing its direction d,
// E = pi x sum(L max(0, d.w)) / sum(max(0, d.w)) (the cosine-weighted mean radiance times pi: a
// uniform sky of radiance L gives pi L), then keeps `hysteresis` of the stored value. Where the
// new value differs from the stored one by more than the large-change ratio (a light switched,
// an object moved) the lower hysteresis is used, so the probe follows within a few updates:
// only when it falls (see below).
// Stored encoded (ddgiEncodeIrradiance), border copied. Inactive probes are left as they are.
#include "ddgi/ddgi_common.hlsli"

StructuredBuffer<DdgiProbe> gProbes : register(t0);
StructuredBuffer<float4> gRayData : register(t1);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gIrradiance : register(u0);

#include "ddgi/ddgi_blend_common.hlsli"

#define N LUMINA_DDGI_IRRADIANCE_SIZE
groupshared float4 gsTexel[N * N];

float maxComponent(float3 v) {
    return max(v.x, max(v.y, v.z));
}

[numthreads(LUMINA_DDGI_IRRADIANCE_SIZE, LUMINA_DDGI_IRRADIANCE_SIZE, 1)] void main(uint3 group : SV_GroupID, uint t : SV_GroupIndex) {
    BlendTexel texel;
    if (!beginBlend(group.x, t, N, texel)) {
        return;
    }
    const float3 d = texel.direction;
    float3 sum = float3(0.0, 0.0, 0.0);
    float weight = 0.0;
    for (uint r = 0u; r < blendedRayCount(); ++r) {
        const float w = max(0.0, dot(d, gsRayDirection[r].xyz));
        sum += w * gsRayData[r].rgb;
        weight += w;
    }
    const float3 fresh = weight > 0.0 ? LUMINA_PI * sum / weight : float3(0.0, 0.0, 0.0);

    const uint2 tile =
        ddgiTileOrigin(gDdgi.volumes[texel.ref.volume], texel.ref.local, LUMINA_DDGI_IRRADIANCE_TILE);
    const uint2 at = tile + 1u + texel.local;
    const float4 stored = gIrradiance[at];
    const float3 previous = float3(ddgiDecodeIrradiance(stored.r), ddgiDecodeIrradiance(stored.g),
                                   ddgiDecodeIrradiance(stored.b));
    float hysteresis = blendHysteresis();
    // Only a fall is taken as a large change: one ray of an update that catches a small, very
    // bright spot (the ceiling right under a point light) raises a texel many times over, and
    // taking that at the lowered hysteresis left blotches on the Cornell box's floor (relMSE
    // 0.080 against 0.017 a few updates earlier, docs/ddgi.md). Light that appears comes in at
    // the normal rate.
    if (gDdgi.largeChangeRatio * maxComponent(fresh) < maxComponent(previous)) {
        hysteresis = min(hysteresis, gDdgi.changedHysteresis);
    }
    // A fresh probe's stored texels are whatever the atlas held (NaN included): not read at all.
    const float3 e = ddgiSanitise(hysteresis > 0.0 ? lerp(fresh, previous, hysteresis) : fresh);
    const float4 encoded =
        float4(ddgiEncodeIrradiance(e.r), ddgiEncodeIrradiance(e.g), ddgiEncodeIrradiance(e.b), 1.0);
    gIrradiance[at] = encoded;
    gsTexel[t] = encoded;
    GroupMemoryBarrierWithGroupSync();
    uint2 bordered;
    uint interior;
    if (borderTexel(t, N, bordered, interior)) {
        gIrradiance[tile + bordered] = gsTexel[interior];
    }
}
