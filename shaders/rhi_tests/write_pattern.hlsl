// lumina-kernel: cs main
// Every kind of compute binding at once: push constants, a constant buffer, a structured
// input, structured and raw outputs and an rgba16f storage texture.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "rhi_tests/rhi_tests_shared.h"

LUMINA_PUSH_CONSTANTS(WritePatternPush, gPush);
ConstantBuffer<WritePatternConstants> gConstants : register(b0);
StructuredBuffer<PatternElement> gInput : register(t0);
RWStructuredBuffer<PatternElement> gStructured : register(u0);
RWByteAddressBuffer gRaw : register(u1);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gImage : register(u2);

static const uint kRawStride = 4;
static const uint kRawMultiplier = 7;

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    const uint i = id.x;
    if (i < gPush.count) {
        PatternElement element;
        element.a = gInput[i].a * gConstants.multiplier + uint4(gPush.seed, i, 7, 1);
        element.b = float4(float(i), float(gPush.seed), float(i) * gConstants.elementScale, gInput[i].b.w);
        gStructured[i] = element;
        gRaw.Store(i * kRawStride, i * kRawMultiplier + gPush.seed);
    }
    if (i < gPush.width * gPush.height) {
        const uint2 texel = uint2(i % gPush.width, i / gPush.width);
        gImage[texel] = float4(float(texel.x), float(texel.y), float(gPush.seed), gConstants.texelW);
    }
}
