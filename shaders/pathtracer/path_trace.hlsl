// lumina-kernel: cs main
// One sample per pixel of the reference path tracer (gi/pathtracer/path_tracer.cpp), over one
// tile of the image: a camera path with Lambertian scattering, next-event estimation of every
// punctual light and of one emissive triangle per vertex, multiple importance sampling
// (power heuristic) between emitter sampling and BSDF sampling, Russian roulette and a bounce
// limit. Each pixel keeps a running mean and sum of squared deviations (Welford), so the
// image and its variance build up over many short dispatches. docs/pathtracer.md says more;
// docs/conventions.md holds the camera, units and light conventions.
#include "common/bindings.hlsli"
#include "common/bvh_shared.h"
#include "common/camera_shared.h"
#include "common/constants_shared.h"
#include "common/conventions.h"
#include "common/lights_shared.h"
#include "common/scene_shared.h"
#include "pathtracer/pathtracer_shared.h"
#include "pathtracer/random_shared.h"

ConstantBuffer<PathTraceConstants> gConstants : register(b0);
LUMINA_PUSH_CONSTANTS(PathTracePassConstants, gPass);

StructuredBuffer<BvhNode> gBvhNodes : register(t0);
StructuredBuffer<BvhTriangle> gBvhTriangles : register(t1);
StructuredBuffer<PtTriangle> gTriangles : register(t2);
StructuredBuffer<GpuVertex> gVertices : register(t3);
StructuredBuffer<uint> gIndices : register(t4);
StructuredBuffer<GpuInstance> gInstances : register(t5);
StructuredBuffer<GpuMaterial> gMaterials : register(t6);
StructuredBuffer<PtEmitter> gEmitters : register(t7);
StructuredBuffer<PtAliasEntry> gEmitterAlias : register(t8);
StructuredBuffer<GpuLight> gLights : register(t9);
Texture2DArray<float4> gTextures : register(t10);
Texture2D<float4> gSky : register(t11); // latitude-longitude radiance (common/sky_sampling.hlsli)
SamplerState gMaterialSampler : register(s0);

RWStructuredBuffer<float4> gMean : register(u0);  // rgb: radiance; w: luminance
RWStructuredBuffer<float4> gM2 : register(u1);    // sums of squared deviations from the mean
RWStructuredBuffer<uint2> gCounts : register(u2); // x: rays traced; y: non-finite samples dropped
RWStructuredBuffer<PtPixelAovs> gAovs : register(u3);

#define LUMINA_BVH_NODE(i) gBvhNodes[i]
#define LUMINA_BVH_TRIANGLE(i) gBvhTriangles[i]
#include "common/bvh_traversal.hlsli"
#include "pathtracer/material.hlsli"
#include "pathtracer/ray_offset.hlsli"
#include "pathtracer/surface.hlsli"
#define LUMINA_SKY_TEXTURE gSky
#include "common/sky_sampling.hlsli"

// Shadow rays towards a sampled emitter point stop this fraction short of it, so that they
// never hit the emitting triangle itself (t is exact to a few ulps, far below this).
#define PT_SHADOW_SHORTEN 0.9999f

// An orthonormal basis around a unit normal (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017).
float3 ptToWorld(float3 local, float3 n) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    float3 t = float3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    float3 bt = float3(b, s + n.y * n.y * a, -n.y);
    return t * local.x + bt * local.y + n * local.z;
}

bool ptFinite(float3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// Solid-angle pdf of reaching the emitter `e` at distance `distance` by emitter sampling.
float ptEmitterSolidAnglePdf(PtEmitter e, float distance, float cosLight) {
    return e.edge1AndPdf.w * distance * distance / max(cosLight * e.v0AndArea.w, 1e-30f);
}

struct PathState {
    float3 throughput;
    float3 direct;   // paths of at most one bounce
    float3 indirect; // paths of two or more
    uint rays;
};

void ptAddLight(inout PathState path, uint bounces, float3 radiance) {
    if (bounces <= 1u) {
        path.direct += radiance;
    } else {
        path.indirect += radiance;
    }
}

// Next-event estimation of every punctual light at surface point p (bounces: scattering
// events of the paths this adds, counting this vertex).
void ptSamplePunctualLights(inout PathState path, uint bounces, float3 origin, float3 p, float3 ns, float3 ng,
                            float3 albedo) {
    for (uint i = 0u; i < gConstants.lightCount; ++i) {
        LightSample ls = evaluateLight(gLights[i], p);
        float cosSurface = dot(ns, ls.direction);
        if (cosSurface <= 0.0f || dot(ng, ls.direction) <= 0.0f || all(ls.irradiance <= 0.0f)) {
            continue;
        }
        path.rays += 1u;
        if (!bvhTraceAny(origin, ls.direction, 0.0f, ls.distance)) {
            ptAddLight(path, bounces,
                       path.throughput * albedo * LUMINA_INV_PI * ls.irradiance * cosSurface);
        }
    }
}

// Next-event estimation of one emissive triangle chosen by power, weighted against BSDF
// sampling by the power heuristic.
void ptSampleEmitter(inout PathState path, inout PtRng rng, uint bounces, float3 origin, float3 ns, float3 ng,
                     float3 albedo) {
    uint count = gConstants.emitterCount;
    float uPick = ptRngNext(rng);
    float uKeep = ptRngNext(rng);
    float2 bary = ptSampleTriangle(ptRngNext(rng), ptRngNext(rng));
    uint index = min(uint(uPick * float(count)), count - 1u);
    PtAliasEntry entry = gEmitterAlias[index];
    if (uKeep >= entry.probability) {
        index = entry.alias;
    }
    PtEmitter e = gEmitters[index];
    float3 lightPoint = e.v0AndArea.xyz + e.edge1AndPdf.xyz * bary.x + e.edge2AndSign.xyz * bary.y;
    float3 toLight = lightPoint - origin;
    float distance2 = dot(toLight, toLight);
    if (distance2 <= 0.0f) {
        return;
    }
    float distance = sqrt(distance2);
    float3 wi = toLight / distance;
    float cosSurface = dot(ns, wi);
    if (cosSurface <= 0.0f || dot(ng, wi) <= 0.0f) {
        return;
    }
    float3 lightNormal = normalize(cross(e.edge1AndPdf.xyz, e.edge2AndSign.xyz)) * e.edge2AndSign.w;
    float cosFront = -dot(lightNormal, wi);
    PtTriangle tri = gTriangles[e.info.x];
    GpuMaterial material = gMaterials[tri.info.z >> 8u];
    float2 uv = float2(0.0f, 0.0f);
    if (material.textures.y != LUMINA_NO_TEXTURE_LAYER) { // texture coordinates only for a texture
        float3 worldNormal;
        ptInterpolateAttributes(tri, bary, worldNormal, uv);
    }
    float3 le = emittedRadiance(ptEmission(material, uv), material.textures.z, cosFront);
    if (all(le <= 0.0f)) {
        return;
    }
    float lightPdf = ptEmitterSolidAnglePdf(e, distance, abs(cosFront));
    float bsdfPdf = cosSurface * LUMINA_INV_PI;
    float weight = ptPowerHeuristic(lightPdf, bsdfPdf);
    path.rays += 1u;
    if (!bvhTraceAny(origin, wi, 0.0f, distance * PT_SHADOW_SHORTEN)) {
        ptAddLight(path, bounces,
                   path.throughput * albedo * LUMINA_INV_PI * le * (cosSurface * weight / lightPdf));
    }
}

[numthreads(LUMINA_SCREEN_GROUP_SIZE, LUMINA_SCREEN_GROUP_SIZE, 1)] void main(uint3 id
                                                        : SV_DispatchThreadID) {
    uint2 pixel = uint2(gPass.tileX + id.x, gPass.tileY + id.y);
    uint width = gConstants.width;
    if (pixel.x >= width || pixel.y >= gConstants.height) {
        return;
    }
    uint pixelIndex = pixel.y * width + pixel.x;
    uint flags = gConstants.flags;
    uint maxBounces = gConstants.maxBounces;
    PtRng rng = ptRngCreate(gConstants.seed, pixelIndex, gPass.sampleIndex);

    float2 jitter = float2(0.5f, 0.5f);
    if ((flags & LUMINA_PT_FLAG_JITTER) != 0u) {
        jitter = float2(ptRngNext(rng), ptRngNext(rng));
    }
    float3 origin = cameraPosition(gConstants.camera);
    float3 direction = cameraRayDirection(gConstants.camera, float2(pixel) + jitter);

    PathState path;
    path.throughput = float3(1.0f, 1.0f, 1.0f);
    path.direct = float3(0.0f, 0.0f, 0.0f);
    path.indirect = float3(0.0f, 0.0f, 0.0f);
    path.rays = 0u;
    float3 firstAlbedo = float3(0.0f, 0.0f, 0.0f);
    float3 firstNormal = float3(0.0f, 0.0f, 0.0f);
    float bsdfPdf = 0.0f; // solid-angle pdf of the last BSDF sample (unused for the camera ray)

    for (uint bounces = 0u;; ++bounces) {
        path.rays += 1u;
        BvhHit hit = bvhTraceClosest(origin, direction, 0.0f, LUMINA_LIGHT_INFINITE_DISTANCE);
        if (hit.primId == LUMINA_BVH_NO_HIT) {
            ptAddLight(path, bounces, path.throughput * skyRadiance(direction));
            break;
        }
        PtSurface s = ptLoadSurface(hit.triangleIndex, hit.primId, hit.bary);
        GpuMaterial material = gMaterials[s.material];
        float cosFront = -dot(s.frontNormal, direction);

        // Emission met by the camera ray or by a BSDF sample, MIS-weighted against emitter sampling.
        if (s.emitter != LUMINA_PT_NOT_EMISSIVE) {
            float3 le = emittedRadiance(ptEmission(material, s.uv), material.textures.z, cosFront);
            float weight = 1.0f;
            if (bounces > 0u) {
                float lightPdf = ptEmitterSolidAnglePdf(gEmitters[s.emitter], hit.t, abs(cosFront));
                weight = ptPowerHeuristic(bsdfPdf, lightPdf);
            }
            ptAddLight(path, bounces, path.throughput * le * weight);
        }

        // Both sides of every surface scatter: shade the side the ray came from.
        float side = cosFront >= 0.0f ? 1.0f : -1.0f;
        float3 ng = s.frontNormal * side;
        float3 ns = s.shadingNormal * side;
        float3 albedo = ptAlbedo(material, s.uv);
        if (bounces == 0u) {
            firstAlbedo = albedo;
            firstNormal = ns;
        }
        if (bounces >= maxBounces) {
            break;
        }
        float3 p = s.position;
        origin = ptOffsetRayOrigin(p, ng);
        ptSamplePunctualLights(path, bounces + 1u, origin, p, ns, ng, albedo);
        if (gConstants.emitterCount > 0u) {
            ptSampleEmitter(path, rng, bounces + 1u, origin, ns, ng, albedo);
        }

        // Cosine-weighted BSDF sample: the Lambertian weight f cos / pdf is the albedo.
        float3 local = ptSampleCosineHemisphere(ptRngNext(rng), ptRngNext(rng));
        direction = normalize(ptToWorld(local, ns));
        float cosOut = dot(ns, direction);
        if (cosOut <= 0.0f || dot(ng, direction) <= 0.0f) {
            break; // below the geometric surface: the shading normal's hemisphere leaks here
        }
        bsdfPdf = cosOut * LUMINA_INV_PI;
        path.throughput *= albedo;

        // Russian roulette (pbrt-v4): survive with probability max(throughput) when below 1.
        float uRoulette = ptRngNext(rng);
        float maxThroughput = max(path.throughput.r, max(path.throughput.g, path.throughput.b));
        if (maxThroughput <= 0.0f) {
            break;
        }
        if (bounces + 1u >= gConstants.rouletteStartBounce && maxThroughput < 1.0f) {
            if (uRoulette >= maxThroughput) {
                break;
            }
            path.throughput /= maxThroughput;
        }
    }

    float3 radiance = path.direct + path.indirect;
    uint dropped = 0u;
    if (!ptFinite(radiance)) {
        radiance = float3(0.0f, 0.0f, 0.0f);
        path.direct = radiance;
        path.indirect = radiance;
        dropped = 1u;
    }
    float4 x = float4(radiance, luminance(radiance));
    uint sampleIndex = gPass.sampleIndex;
    if (sampleIndex == 0u) {
        gMean[pixelIndex] = x;
        gM2[pixelIndex] = float4(0.0f, 0.0f, 0.0f, 0.0f);
        gCounts[pixelIndex] = uint2(path.rays, dropped);
    } else {
        float4 mean = gMean[pixelIndex];
        float4 delta = x - mean;
        mean += delta / float(sampleIndex + 1u);
        gMean[pixelIndex] = mean;
        gM2[pixelIndex] += delta * (x - mean);
        gCounts[pixelIndex] += uint2(path.rays, dropped);
    }
    if ((flags & LUMINA_PT_FLAG_AOVS) != 0u) {
        PtPixelAovs sampleAovs;
        sampleAovs.albedo = float4(firstAlbedo, 0.0f);
        sampleAovs.normal = float4(firstNormal, 0.0f);
        sampleAovs.direct = float4(path.direct, 0.0f);
        sampleAovs.indirect = float4(path.indirect, 0.0f);
        if (sampleIndex == 0u) {
            gAovs[pixelIndex] = sampleAovs;
        } else {
            float invCount = 1.0f / float(sampleIndex + 1u);
            PtPixelAovs aovs = gAovs[pixelIndex];
            aovs.albedo += (sampleAovs.albedo - aovs.albedo) * invCount;
            aovs.normal += (sampleAovs.normal - aovs.normal) * invCount;
            aovs.direct += (sampleAovs.direct - aovs.direct) * invCount;
            aovs.indirect += (sampleAovs.indirect - aovs.indirect) * invCount;
            gAovs[pixelIndex] = aovs;
        }
    }
}
