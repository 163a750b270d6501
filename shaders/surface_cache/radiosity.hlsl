// lumina-kernel: cs trace
// lumina-kernel: cs filter
// lumina-kernel: cs integrate
// Surface radiosity (gi/surface_cache/radiosity_pass.h): one bounce of diffuse light between
// the cached surfaces per update.
//   trace:     one thread per probe (every 4x4 texels) of the listed tiles: 16 rays over the
//              hemisphere through the global SDF, each starting on the line through the
//              probe's own point of the surface (surfaceLineStart), each hit that is not a
//              graze of an open surface's shell (sdfFollowGraze) reading the voxel
//              lighting (the last update's outgoing radiance), each ray that leaves the scene
//              the sky (common/sky_sampling.hlsli), projected to L1 SH whose irradiance at the
//              probe's normal is the rays' exact cosine-weighted sum (withIrradianceAt); counts
//              what its rays found (RadiosityRayStats).
//   filter:    each probe averaged with its 4 neighbours on the same card and plane.
//   integrate: one thread per texel: the filtered SH's irradiance at the texel's normal into
//              the indirect layer, negatives clamped.
// Rays are a 4 x 4 stratified grid, uniform in cos(theta) and phi, moved within its cells each
// update and shifted per probe (gridOffset), opposite azimuths mirroring their offset in
// cos(theta): with the uniform pdf 1 / (2 pi) the SH projection of a uniform hemisphere of
// radiance L is exact on every update (each band's mean cos(theta) is its centre, so the mean is
// 1/2; opposite azimuths cancel), and its L1 irradiance at the probe's normal is exactly pi L, so
// a furnace converges to its analytic value, not to an estimator's bias.
#include "common/constants_shared.h"
#include "sdf/sdf_scene_bindings.hlsli"
#include "sdf/surface_line_start.hlsli"
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"
// After the tracing library it follows grazes for.
#include "sdf/open_surface_graze.hlsli"

LUMINA_PUSH_CONSTANTS(RadiosityConstants, gConstants);
Texture2DArray<float4> gSurface : register(t6); // layer 0 normal (a = captured)
Texture2D<uint> gTileOwner : register(t7);
StructuredBuffer<SurfaceCard> gCards : register(t8);
Texture2D<float> gCaptureDepth : register(t9);
StructuredBuffer<uint> gTiles : register(t10);
Texture3D<float4> gVoxelLighting : register(t11);
StructuredBuffer<RadiosityProbe> gProbesIn : register(t12); // filter: traced; integrate: filtered
Texture2D<float4> gSky : register(t13);                     // trace: latitude-longitude radiance
RWStructuredBuffer<RadiosityProbe> gProbesOut : register(u0);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gIndirect : register(u1);
RWStructuredBuffer<uint> gRayStats : register(u2); // trace: RadiosityRayStats, summed

#define LUMINA_TILE_OWNER gTileOwner
#define LUMINA_SURFACE_CARD(i) gCards[i]
#define LUMINA_CAPTURE_DEPTH gCaptureDepth
#include "surface_cache/surface_cache_texel.hlsli"
#define LUMINA_VOXEL_LIGHTING gVoxelLighting
#include "surface_cache/voxel_lighting_sampling.hlsli"
#define LUMINA_SKY_TEXTURE gSky
#include "common/sky_sampling.hlsli"

// Sphere-tracing steps per probe ray: the library's 64 run out on rays grazing a wall or
// entering a corner (steps shrink with the distance), and in a closed room a ray that runs out
// reads as a miss, which lost 2.5 % of the light in the furnace at rho = 0.8.
#define LUMINA_RADIOSITY_MAX_STEPS 256u
// Probe texels tried in order: the 2x2 centre of the 4x4 block first, then its border, so a
// probe sits near its block's middle but still exists on a block only partly covered or
// partly under another object.
static const uint2 kProbeTexelOrder[16] = {
    uint2(1, 1), uint2(2, 1), uint2(1, 2), uint2(2, 2), uint2(0, 0), uint2(1, 0), uint2(2, 0), uint2(3, 0),
    uint2(0, 1), uint2(3, 1), uint2(0, 2), uint2(3, 2), uint2(0, 3), uint2(1, 3), uint2(2, 3), uint2(3, 3)};

uint probesPerRow() {
    return gConstants.atlasSize / LUMINA_RADIOSITY_PROBE_SPACING;
}

// Candidate texels for a probe: slots 0-15 are its own block's (kProbeTexelOrder), slots 16-143
// the eight neighbouring blocks' (edges first, then corners: a block in the corner of a wall, the
// ceiling and a divider finds clearance only diagonally), 16 each in the same order. A neighbour's
// texel is taken only where no visible texel of the block has the clearance its rays need: a block
// narrower than the clearance along a concave junction (the floor's first row at a wall's foot once
// card texels are finer than an eighth of a global SDF voxel, the high preset) otherwise started
// its rays inside the wall's shell, every ray hit at once and read the voxel of the wall's far side
// (sunlit_rooms: 85 times the light of the next row; docs/gi.md, energy 23.).
#define LUMINA_RADIOSITY_PROBE_SLOTS 144u
static const int2 kNeighbourBlock[9] = {int2(0, 0),   int2(-1, 0), int2(1, 0),  int2(0, -1), int2(0, 1),
                                        int2(-1, -1), int2(1, -1), int2(-1, 1), int2(1, 1)};

// The atlas texel of `slot` of `probe`; false where that texel lies outside the atlas.
bool probeSlotTexel(uint2 probe, uint slot, out uint2 texel) {
    int2 block = int2(probe) + kNeighbourBlock[slot / 16u];
    int2 t = block * int(LUMINA_RADIOSITY_PROBE_SPACING) + int2(kProbeTexelOrder[slot % 16u]);
    texel = uint2(max(t, int2(0, 0)));
    return all(t >= int2(0, 0)) && all(t < int2(gConstants.atlasSize, gConstants.atlasSize));
}

// The probe (in the atlas's probe grid) of a per-probe tile-list dispatch's thread; false past
// the list.
bool listedProbe(uint2 id, out uint2 probe) {
    probe = uint2(0, 0);
    uint entry, inTile;
    if (!tileListItem(id, gConstants.tileCount, LUMINA_PROBES_PER_TILE, entry, inTile)) {
        return false;
    }
    uint tile = gTiles[entry];
    probe = uint2(tile % gConstants.tilesPerRow, tile / gConstants.tilesPerRow) * LUMINA_PROBES_PER_TILE_SIDE +
            uint2(inTile % LUMINA_PROBES_PER_TILE_SIDE, inTile / LUMINA_PROBES_PER_TILE_SIDE);
    return true;
}

uint probeIndex(uint2 probe) {
    return probe.y * probesPerRow() + probe.x;
}

RadiosityProbe emptyProbe() {
    RadiosityProbe p;
    p.r = float4(0.0f, 0.0f, 0.0f, 0.0f);
    p.g = p.r;
    p.b = p.r;
    p.normalAndTexel = p.r;
    return p;
}

float3 finiteOrZero(float3 v) {
    return (any(isnan(v)) || any(isinf(v))) ? float3(0.0f, 0.0f, 0.0f) : v;
}

// Free space a probe's rays need where they start, in voxels of the cascade there: below the
// trace's hit threshold (0.1 voxel) every ray stops where it starts and the probe reads black. Near
// a concave edge the global SDF's zero crossing runs up to a voxel in front of the true surface,
// so an origin lifted off one wall can sit on the zero crossing of the wall beside it
// (the last row of probes on a Cornell box's side wall, next to the back wall, read black).
#define LUMINA_RADIOSITY_CLEARANCE_VOXELS 0.5f

float originClearance(float3 origin) {
    return LUMINA_RADIOSITY_CLEARANCE_VOXELS * sdfGlobalVoxelSizeAt(origin);
}

// A texel lifted off its surface: the offset is in finest global SDF voxels; where a coarser
// cascade serves the texel, in its own.
float3 liftedOrigin(float3 world, float3 n) {
    return world + gConstants.originOffset * sdfGlobalCascadeScaleAt(world) * n;
}

// Pushes along the SDF's gradient a probe needs at most to reach its clearance: one from a
// wall's zero crossing, two from next to a block's foot (the gradient there also leans into the
// floor).
#define LUMINA_RADIOSITY_CLEARANCE_PUSHES 3u

// A later texel replaces the chosen one only with this much more clearance, as a fraction of the
// clearance needed (1/64 of a voxel): along a wall's zero crossing the texels of a block have the
// same clearance to the rounding of one trilinear sample, and the APIs round differently, so
// without a margin a column of corner probes chose its texel by rounding (D3D12 and Vulkan chose
// differently, and their probes' light differed by up to 0.5).
#define LUMINA_RADIOSITY_CLEARANCE_TIE (1.0f / 32.0f)

// Whether p, projected onto `card` along its axis, lands on one of the card's captured texels. A
// push that carries an origin past the card's edge has gone through the surface that meets the
// card there: an inner wall's top row lifts into the shell of a zero-thickness ceiling, whose coarse
// gradient there may point up, and pushed along it the probe read the sky and the sunlit roof
// (sunlit_rooms at the high preset, whose 9 cm probe blocks hold no texel with clearance under the
// ceiling, read 19 % bright; docs/gi.md, energy, 18.).
bool projectsOntoCard(uint card, float3 p) {
    SurfaceCard c = gCards[card];
    float2 texel = cardToAtlasTexel(c, worldToCardSpace(c, p).xy);
    float2 rectMin = float2(c.atlasRect.xy);
    float2 rectMax = rectMin + float2(c.atlasRect.zw);
    bool inside = all(texel >= rectMin) && all(texel < rectMax);
    uint2 nearest = uint2(clamp(texel, rectMin, rectMax - 1.0f));
    return inside && gSurface.Load(int4(nearest, 0, 0)).a > 0.0f;
}

// Where the rays of a probe on texel `world` of `card` start: lifted off the surface, then pushed
// along the SDF's gradient until it has its clearance; a push that would leave the card's surface
// (projectsOntoCard) lifts further along the normal instead. Not the other way along the card:
// that turned a door jamb's probes towards the lit room, and the shut door's dark room read six
// times its light. A texel beside a block standing on it (a floor texel
// at the block's foot) lifts into the block's zero crossing, up to a voxel inside; its gradient
// leads out of the block on the texel's side. Origins deeper inside are buried
// (atlasTexelBuried) and never traced: a push moves a voxel and a half at most, too little to
// cross a wall from the side the texel faces.
float3 probeRayOriginAt(float3 world, float3 n, uint card) {
    float3 origin = liftedOrigin(world, n);
    for (uint push = 0u; push < LUMINA_RADIOSITY_CLEARANCE_PUSHES; ++push) {
        float distance = sdfSampleGlobal(origin);
        float clearance = originClearance(origin);
        if (distance >= clearance) {
            break;
        }
        float3 gradient = sdfGlobalNormal(origin);
        float3 pushed = origin + (clearance - distance) * gradient;
        if (!projectsOntoCard(card, pushed)) {
            pushed = origin + (clearance - distance) * n;
        }
        origin = pushed;
    }
    return origin;
}

// Where this update's rays of `probe` sit on their 4 x 4 grid, as fractions of a cell. Over
// updates: the R2 sequence (Roberts 2018), the plastic number's two steps, so that successive
// updates fill the cells evenly in both coordinates; in integer arithmetic (2^32 times each step),
// exact however many updates have run. x rotates phi; y places cos(theta) in its band. Per probe:
// a hashed shift of both (a Cranley-Patterson rotation), so that neighbouring probes look in
// different directions. With cos(theta) fixed at the bands' centres a probe saw four elevations
// only: a source seen through a doorway between two of them was missed by every update, and one
// that filled part of a band counted as filling all of it. With one grid for every probe, the
// error of 16 rays was shared by a whole wall, as rings (fixed elevations) or spokes (moved
// ones); shifted per probe it is noise, which the filter and the refinement passes average
// (docs/gi.md, energy, 19.). The shift is a property of the surface, not of where the atlas
// holds it: hashed from the card and the probe's place on the card, so a card re-placed in the
// atlas (a moved or rescaled instance, a new density) converges to the same light; hashed from the
// atlas position, a card re-placed after a one-frame scale of 1e6 averaged other ray sets than a
// run without it, and the screen probes, steered by that light, stayed 0.05 apart (PoisonStress,
// bound 0.03; docs/gi.md, energy 22.). The update index is read once, as an integer: vkd3d-shader
// merges a float and an integer cast of one value (docs/d3d12.md).
float2 gridOffset(uint updateIndex, uint card, uint2 probeOnCard) {
    uint shift = hashUint(card ^ hashUint(probeOnCard.x ^ hashUint(probeOnCard.y)));
    uint2 steps = uint2(3242174889u, 2447445414u) * updateIndex + uint2(shift, hashUint(shift));
    return float2(steps >> 8) * (1.0f / 16777216.0f);
}

// The free space a sliding ray start keeps (surface_line_start.hlsli), as a fraction of the
// origin's clearance. A pushed origin sits at its clearance, so a slide that kept all of it never
// found room for a first step and the ray started where the lift put it: an overhead source seen
// from there looks larger, and the first bounce read 13 % bright (two_rooms; 1.05 with this
// margin; docs/gi.md, energy 20.).
#define LUMINA_RADIOSITY_SLIDE_MARGIN 0.5f

// Irradiance of L1 SH at normal n, the cosine lobe's band factors pi and 2 pi / 3
// (Ramamoorthi and Hanrahan 2001), unclamped.
float shIrradianceL1(float4 sh, float3 n) {
    return LUMINA_PI * LUMINA_SH_Y00 * sh.x + (2.0f * LUMINA_PI / 3.0f) * LUMINA_SH_Y1 * dot(sh.yzw, n);
}

// L1 can dip below zero opposite bright light: clamped.
float shIrradiance(float4 sh, float3 n) {
    return max(shIrradianceL1(sh, n), 0.0f);
}

// `sh` with its L0 moved so that its irradiance at n is `irradiance`, its direction kept. L1 is a
// low-pass of the cosine lobe: under a source overhead it reads a quarter low, and around a
// source near the horizon high, and that loss had been cancelling the excess of rays that started
// above their texel (docs/gi.md, energy 17., 20.). The rays' own cosine-weighted sum is the exact
// estimate at the probe's normal; the texels of a probe's block share that normal, and the
// direction still serves the filter's neighbours, whose normals may differ by a little.
float4 withIrradianceAt(float4 sh, float3 n, float irradiance) {
    sh.x += (irradiance - shIrradianceL1(sh, n)) / (LUMINA_PI * LUMINA_SH_Y00);
    return sh;
}

// The texel a probe's rays start from, as chosen so far (trace).
struct ProbeTexelChoice {
    uint slot; // probeSlotTexel finds the texel again
    uint card;
    float3 n;
    float3 world;
    float clearance; // the lifted origin's SDF less the clearance it needs
};

// Takes `slot` of `probe` in place of the choice so far if it is captured and clearer by the tie
// margin (the first captured one always). `sameCard`: LUMINA_NO_CARD for the block's own texels,
// else the card a neighbour block's texel must belong to.
void considerProbeSlot(uint2 probe, uint slot, uint sameCard, inout ProbeTexelChoice choice) {
    uint2 candidate;
    bool inAtlas = probeSlotTexel(probe, slot, candidate);
    float4 normal = gSurface.Load(int4(candidate, 0, 0));
    uint candidateCard = atlasTexelCard(candidate);
    if (!inAtlas || normal.a == 0.0f || candidateCard == LUMINA_NO_CARD ||
        (sameCard != LUMINA_NO_CARD && candidateCard != sameCard)) {
        return;
    }
    float3 candidateNormal = normalize(normal.xyz);
    float3 candidateWorld = atlasTexelWorldPosition(gCards[candidateCard], candidate);
    float3 lifted = liftedOrigin(candidateWorld, candidateNormal);
    float needed = originClearance(lifted);
    float clearance = sdfSampleGlobal(lifted) - needed;
    if (choice.card == LUMINA_NO_CARD ||
        clearance > choice.clearance + LUMINA_RADIOSITY_CLEARANCE_TIE * needed) {
        choice.slot = slot;
        choice.card = candidateCard;
        choice.n = candidateNormal;
        choice.world = candidateWorld;
        choice.clearance = clearance;
    }
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void trace(uint3 id
                                                        : SV_DispatchThreadID) {
    uint2 probe;
    if (!listedProbe(id.xy, probe)) {
        return;
    }
    // The probe's texel: the first in kProbeTexelOrder whose ray origin has the clearance its rays
    // need (a block straddling the edge of an object standing on the surface must not start its
    // rays inside that object, nor a block in a corner on the other wall's zero crossing); the
    // clearest captured one when none does.
    ProbeTexelChoice choice;
    choice.slot = 0u;
    choice.card = LUMINA_NO_CARD;
    choice.n = float3(0.0f, 0.0f, 1.0f);
    choice.world = float3(0.0f, 0.0f, 0.0f);
    choice.clearance = -1e30f;
    for (uint i = 0u; i < 16u && choice.clearance < 0.0f; ++i) {
        considerProbeSlot(probe, i, LUMINA_NO_CARD, choice);
    }
    // Only a visible texel short of clearance looks further: an empty or buried block keeps no light.
    bool lookAround =
        choice.card != LUMINA_NO_CARD && choice.clearance < 0.0f && !atlasTexelBuried(choice.world, choice.n);
    for (uint j = 16u; j < LUMINA_RADIOSITY_PROBE_SLOTS && lookAround && choice.clearance < 0.0f; ++j) {
        considerProbeSlot(probe, j, choice.card, choice);
    }
    uint card = choice.card;
    uint slot = choice.slot;
    float3 n = choice.n;
    float3 world = choice.world;
    if (card == LUMINA_NO_CARD || atlasTexelBuried(world, n)) {
        gProbesOut[probeIndex(probe)] = emptyProbe(); // its texels get no indirect light
        return;
    }
    float3 origin = probeRayOriginAt(world, n, card);
    // An orthonormal frame around n (Duff et al. 2017, branchless).
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    float3 t1 = float3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    float3 t2 = float3(b, s + n.y * n.y * a, -n.y);

    SdfTraceParams params = sdfDefaultTraceParams(gConstants.maxDistance);
    params.maxSteps = LUMINA_RADIOSITY_MAX_STEPS;
    float2 offset =
        gridOffset(gConstants.updateIndex, card, probe - gCards[card].atlasRect.xy / LUMINA_RADIOSITY_PROBE_SPACING);
    // Each ray's direction and start, then every ray marched in one loop: a thread whose ray ends
    // starts its next one at once, so that the threads of a wave, whose probes look in different
    // directions (gridOffset), each take about the sum of their 16 rays' steps rather than all
    // waiting, ray after ray, for the longest of them (on lavapipe the per-probe shift had cost
    // half the trace again; docs/surface_cache.md#cost-of-the-radiosity-trace).
    float3 rayDirection[LUMINA_RADIOSITY_RAYS];
    float3 rayStart[LUMINA_RADIOSITY_RAYS];
    float rayCosTheta[LUMINA_RADIOSITY_RAYS];
    for (uint ray = 0u; ray < LUMINA_RADIOSITY_RAYS; ++ray) {
        uint column = ray % LUMINA_RADIOSITY_RAYS_PER_SIDE;
        // Opposite azimuths (columns 0 and 2, 1 and 3) share an elevation offset and the other
        // pair takes its mirror, so each band's mean cos(theta) stays at its centre and a uniform
        // hemisphere still projects exactly on every update.
        float inBand = (column & 1u) == 0u ? offset.y : 1.0f - offset.y;
        float cosTheta =
            (float(ray / LUMINA_RADIOSITY_RAYS_PER_SIDE) + inBand) / float(LUMINA_RADIOSITY_RAYS_PER_SIDE);
        float phi = 2.0f * LUMINA_PI * (float(column) + offset.x) /
                    float(LUMINA_RADIOSITY_RAYS_PER_SIDE);
        float sinTheta = sqrt(max(1.0f - cosTheta * cosTheta, 0.0f));
        float3 dir = normalize(sinTheta * cos(phi) * t1 + sinTheta * sin(phi) * t2 + cosTheta * n);
        rayDirection[ray] = dir;
        rayCosTheta[ray] = cosTheta;
        rayStart[ray] =
            surfaceLineStartRaised(origin, world, n, dir, cosTheta,
                                   LUMINA_RADIOSITY_SLIDE_MARGIN * LUMINA_RADIOSITY_CLEARANCE_VOXELS);
    }
    float rayEndT[LUMINA_RADIOSITY_RAYS];
    uint rayEnd[LUMINA_RADIOSITY_RAYS]; // status | steps << 8
    {
        uint ray = 0u;
        uint status;
        SdfGlobalMarch march = sdfGlobalMarchBegin(rayStart[0], rayDirection[0], 0.0f, params, status);
        while (ray < LUMINA_RADIOSITY_RAYS) {
            if (status == LUMINA_SDF_MARCH_GOING) {
                status = sdfGlobalMarchStep(march, params);
            }
            if (status != LUMINA_SDF_MARCH_GOING) {
                rayEndT[ray] = march.t;
                rayEnd[ray] = status | (march.steps << 8u);
                ++ray;
                if (ray < LUMINA_RADIOSITY_RAYS) {
                    march = sdfGlobalMarchBegin(rayStart[ray], rayDirection[ray], 0.0f, params, status);
                }
            }
        }
    }
    float4 shR = float4(0.0f, 0.0f, 0.0f, 0.0f);
    float4 shG = shR;
    float4 shB = shR;
    float3 irradiance = float3(0.0f, 0.0f, 0.0f);
    uint stats[LUMINA_RADIOSITY_STAT_COUNT] = {0u, 0u, 0u, 0u, 0u, 0u};
    for (uint ray = 0u; ray < LUMINA_RADIOSITY_RAYS; ++ray) {
        float3 dir = rayDirection[ray];
        float cosTheta = rayCosTheta[ray];
        SdfHit hit = sdfGlobalMarchHit(rayStart[ray], dir, rayEndT[ray], rayEnd[ray] >> 8u,
                                       rayEnd[ray] & 0xFFu, params);
        hit = sdfFollowGraze(hit, dir, params);
        // A ray that leaves the scene sees the sky. One that ran out of steps (grazing a wall, deep
        // in a corner) is a miss too, but it is still inside: it sees nothing rather than a sky
        // that a closed room would not show it.
        float3 radiance = float3(0.0f, 0.0f, 0.0f);
        stats[LUMINA_RADIOSITY_STAT_RAYS] += 1u;
        if (sdfIsMiss(hit)) {
            if (hit.ids.w < params.maxSteps) {
                radiance = skyRadiance(dir);
                stats[LUMINA_RADIOSITY_STAT_LEFT_SCENE] += 1u;
            } else {
                stats[LUMINA_RADIOSITY_STAT_OUT_OF_STEPS] += 1u;
            }
        } else {
            float3 gradient = hit.normalAndCoverage.xyz;
            float3 hitNormal = sdfFacingNormal(gradient, dir, hit.positionAndT.w);
            float4 seen = voxelLightingSeenSide(gConstants.grid, hit.positionAndT.xyz, hitNormal, gradient,
                                                sdfSeenFrom(dir, hit.positionAndT.w));
            radiance = finiteOrZero(seen.rgb);
            stats[LUMINA_RADIOSITY_STAT_HITS] += 1u;
            stats[LUMINA_RADIOSITY_STAT_GRADIENT_SIDE] += seen.a < 0.0f ? 1u : 0u;
            stats[LUMINA_RADIOSITY_STAT_UNLIT_HITS] += seen.a == 0.0f ? 1u : 0u;
        }
        // Monte Carlo projection with the uniform hemisphere pdf 1 / (2 pi).
        float4 basis =
            float4(LUMINA_SH_Y00, LUMINA_SH_Y1 * dir) * (2.0f * LUMINA_PI / float(LUMINA_RADIOSITY_RAYS));
        shR += radiance.r * basis;
        shG += radiance.g * basis;
        shB += radiance.b * basis;
        irradiance += radiance * (cosTheta * 2.0f * LUMINA_PI / float(LUMINA_RADIOSITY_RAYS));
    }
    for (uint k = 0u; k < LUMINA_RADIOSITY_STAT_COUNT; ++k) {
        uint ignored;
        if (stats[k] != 0u) {
            InterlockedAdd(gRayStats[k], stats[k], ignored);
        }
    }
    RadiosityProbe result;
    result.r = withIrradianceAt(shR, n, irradiance.r);
    result.g = withIrradianceAt(shG, n, irradiance.g);
    result.b = withIrradianceAt(shB, n, irradiance.b);
    result.normalAndTexel = float4(n, float(slot + 1u));
    // Refinement (radiosity_schedule.h): the mean of this trace and the history, weighted
    // 1 / (k + 1) for the k-th pass, so that rotated ray sets average out; a convex combination,
    // so it never adds energy.
    float blend = gConstants.temporalBlend;
    RadiosityProbe history = gProbesOut[probeIndex(probe)];
    if (blend < 1.0f && history.normalAndTexel.w != 0.0f) {
        result.r = lerp(history.r, result.r, blend);
        result.g = lerp(history.g, result.g, blend);
        result.b = lerp(history.b, result.b, blend);
    }
    gProbesOut[probeIndex(probe)] = result;
}

// Where a traced probe's rays started: its texel (slot w - 1, probeSlotTexel) lifted off the
// surface as the trace lifts it. Recomputed, not stored: the gradient's push is the same.
float3 probeRayOrigin(uint2 probe, RadiosityProbe traced) {
    uint2 texel;
    probeSlotTexel(probe, uint(traced.normalAndTexel.w) - 1u, texel);
    uint card = atlasTexelCard(texel);
    return probeRayOriginAt(atlasTexelWorldPosition(gCards[card], texel), traced.normalAndTexel.xyz, card);
}

// Sphere-traces the global SDF from one probe's ray origin to another's: a neighbour on the same
// card and plane may still stand behind a thin object on that plane (a door standing on a floor
// card that runs through two rooms), and blending it would carry its light through the object.
// Both origins start with half a voxel of clearance (probeRayOriginAt), above the hit threshold,
// so the surface they share never blocks; running out of steps counts as blocked.
#define LUMINA_RADIOSITY_FILTER_STEPS 32u
bool probeSeesProbe(float3 from, float3 to) {
    float3 d = to - from;
    float distance = length(d);
    if (distance <= 0.0f) {
        return true;
    }
    SdfTraceParams params = sdfDefaultTraceParams(distance);
    params.maxSteps = LUMINA_RADIOSITY_FILTER_STEPS;
    SdfHit hit = sdfTraceGlobal(from, d / distance, 0.0f, params);
    return sdfIsMiss(hit) && hit.ids.w < params.maxSteps;
}

    [numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void filter(uint3 id
                                       : SV_DispatchThreadID) {
    uint2 probe;
    if (!listedProbe(id.xy, probe)) {
        return;
    }
    RadiosityProbe centre = gProbesIn[probeIndex(probe)];
    if (centre.normalAndTexel.w == 0.0f) {
        gProbesOut[probeIndex(probe)] = centre;
        return;
    }
    uint card = atlasTexelCard(probe * LUMINA_RADIOSITY_PROBE_SPACING);
    float3 origin = probeRayOrigin(probe, centre);
    RadiosityProbe sum = centre;
    float count = 1.0f;
    int2 offsets[4] = {int2(-1, 0), int2(1, 0), int2(0, -1), int2(0, 1)};
    int side = int(probesPerRow());
    for (uint i = 0u; i < 4u; ++i) {
        int2 q = int2(probe) + offsets[i];
        if (any(q < 0) || any(q >= side)) {
            continue;
        }
        RadiosityProbe neighbour = gProbesIn[probeIndex(uint2(q))];
        // Same card and about the same plane: never blend light across an edge or a crease.
        bool similar = neighbour.normalAndTexel.w != 0.0f &&
                       dot(neighbour.normalAndTexel.xyz, centre.normalAndTexel.xyz) > gConstants.filterMinCosine &&
                       atlasTexelCard(uint2(q) * LUMINA_RADIOSITY_PROBE_SPACING) == card;
        // A separate test, not one more &&: HLSL before 2021 evaluates both sides, and an empty
        // neighbour (w = 0) has no texel to find its origin on.
        if (similar) {
            similar = probeSeesProbe(origin, probeRayOrigin(uint2(q), neighbour));
        }
        if (similar) {
            sum.r += neighbour.r;
            sum.g += neighbour.g;
            sum.b += neighbour.b;
            count += 1.0f;
        }
    }
    sum.r /= count;
    sum.g /= count;
    sum.b /= count;
    sum.normalAndTexel = centre.normalAndTexel;
    gProbesOut[probeIndex(probe)] = sum;
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void integrate(uint3 id
                                      : SV_DispatchThreadID) {
    uint entry, item;
    if (!tileListItem(id.xy, gConstants.tileCount, LUMINA_ATLAS_TILE_SIZE * LUMINA_ATLAS_TILE_SIZE, entry,
                      item)) {
        return;
    }
    uint2 texel = tileListTexel(gTiles[entry], gConstants.tilesPerRow, item);
    float4 normal = gSurface.Load(int4(texel, 0, 0));
    RadiosityProbe probe = gProbesIn[probeIndex(texel / LUMINA_RADIOSITY_PROBE_SPACING)];
    float3 irradiance = float3(0.0f, 0.0f, 0.0f);
    if (normal.a != 0.0f && probe.normalAndTexel.w != 0.0f) {
        float3 n = normalize(normal.xyz);
        irradiance = finiteOrZero(
            float3(shIrradiance(probe.r, n), shIrradiance(probe.g, n), shIrradiance(probe.b, n)));
    }
    gIndirect[texel] =
        roundToHalfDithered(float4(irradiance, 1.0f), ditherOf(uint3(texel, 1u), gConstants.updateIndex));
}
