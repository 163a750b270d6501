// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// lumina-kernel: vs clearVsMain
// lumina-kernel: ps clearPsMain
// Card capture (gi/surface_cache/card_capture_pass.h): a card's instance drawn orthographically
// along the card's normal into the card's atlas rectangle (the viewport), writing albedo, world
// normal and material in one pass. Card space (surface_card_shared.h) is the projection:
// u, v across the rectangle, z through the card's depth slab, so the depth test keeps the
// surface nearest the capture plane and the slab's ends clip away what other cards hold.
// clearVsMain / clearPsMain first reset the rectangle: zero texels, depth at the slab's back.
#include "common/bindings.hlsli"
#include "common/instance_transform.hlsli"
#include "common/lights_shared.h"
#include "common/scene_shared.h"
#include "surface_cache/card_capture_shared.h"
#include "surface_cache/surface_cache_lighting_shared.h"
#include "surface_cache/surface_card_shared.h"

LUMINA_PUSH_CONSTANTS(CardCaptureConstants, gDraw);
StructuredBuffer<GpuVertex> gVertices : register(t0);
StructuredBuffer<GpuInstance> gInstances : register(t1);
StructuredBuffer<GpuMaterial> gMaterials : register(t2);
Texture2DArray<float4> gTextures : register(t3);
StructuredBuffer<SurfaceCard> gCards : register(t4);
SamplerState gMaterialSampler : register(s0);

// Albedo is rounded to one of its two neighbouring half-float values, up with the probability
// that makes the mean over texels the material's (roundToHalfDithered, a fixed dither per atlas
// texel), so that the write stores it exactly and the light a surface reflects is, on average,
// the material's: in a closed scene the radiance is Le / (1 - rho), 100 times as sensitive to rho
// as rho itself at rho = 0.99, where rounding every texel down (to 0.989746) lost 2.5 % and
// rounding to nearest (0.990234) gained 2.4 %; RGBA8's 1/255 steps alone moved the rho = 0.95
// furnace 1.9 % (docs/surface_cache.md, docs/gi.md).

struct Varyings {
    float4 position : SV_Position;
    float3 normal : TEXCOORD0;
    float2 uv : TEXCOORD1;
};

struct CaptureTargets {
    float4 albedo
        : SV_Target0; // RGBA16F: linear albedo, dithered to a half; a = 1 where a surface was captured
    float4 normal : SV_Target1;   // RGBA16F: unit world normal on the card's side; a = 1
    float4 material : SV_Target2; // RGBA16F: emitted radiance; a = material index
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    const GpuVertex vertex = gVertices[vertexId];
    const GpuInstance instance = gInstances[gDraw.instance];
    const float3 world = instancePointToWorld(instance, vertex.positionU.xyz);
    const float3 card = worldToCardSpace(gCards[gDraw.card], world);
    Varyings output;
    // The viewport is the card's rectangle: u runs right, v down the atlas while clip y runs up
    // (both backends: the Vulkan one flips its viewport).
    output.position = float4(2.0 * card.x - 1.0, 1.0 - 2.0 * card.y, card.z, 1.0);
    output.normal = instanceNormalToWorld(instance, vertex.normalV.xyz);
    output.uv = float2(vertex.positionU.w, vertex.normalV.w);
    return output;
}

float3 sampleLayer(uint layer, float2 uv) {
    return sampleMaterialLayer(gTextures, gMaterialSampler, layer, uv);
}

CaptureTargets psMain(Varyings input) {
    const GpuMaterial material = gMaterials[gDraw.material];
    const SurfaceCard card = gCards[gDraw.card];
    float3 normal = normalize(input.normal);
    // The capture camera looks along -cardNormal: a surface turned away from it is a back face
    // (two-sided cards hold those), shaded with its normal turned towards the card as the
    // GBuffer turns it towards the viewer.
    const float cosFront = dot(normal, card.normalAndPadding.xyz);
    if (cosFront < 0.0) {
        normal = -normal;
    }
    CaptureTargets output;
    const float3 albedo = material.baseColor.rgb * sampleLayer(material.textures.x, input.uv);
    output.albedo = float4(
        roundToHalfDithered(float4(albedo, 1.0), ditherOf(uint3(uint2(input.position.xy), 2u), 0u)).rgb, 1.0);
    output.normal = float4(normal, 1.0);
    const float3 emission = material.emission.rgb * sampleLayer(material.textures.y, input.uv);
    output.material = float4(emittedRadiance(emission, material.textures.z, cosFront), float(gDraw.material));
    return output;
}

// A triangle covering the viewport at depth 1 (the back of the card's slab).
float4 clearVsMain(uint vertexId : SV_VertexID) : SV_Position {
    const float2 corner = float2(float((vertexId << 1) & 2u), float(vertexId & 2u));
    return float4(corner * 2.0 - 1.0, 1.0, 1.0);
}

CaptureTargets clearPsMain() {
    CaptureTargets output;
    output.albedo = float4(0.0, 0.0, 0.0, 0.0);
    output.normal = float4(0.0, 0.0, 0.0, 0.0);
    output.material = float4(0.0, 0.0, 0.0, 0.0);
    return output;
}
