#ifndef LUMINA_RHI_TESTS_SHARED_H
#define LUMINA_RHI_TESTS_SHARED_H
// Constants and buffer elements of the RHI conformance kernels (tests/rhi/), shared by the
// C++ tests and the HLSL kernels in this folder.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

// Push constants of the buffer-chain kernels (chain_seed, chain_step, accumulate):
//   chain_seed:  out[i] = i * multiplier + addend
//   chain_step:  out[i] = in[i] * multiplier + addend
//   accumulate:  data[i] += addend + i
struct ChainConstants {
    uint count;
    uint multiplier;
    uint addend;
    uint pad;
};
LUMINA_STATIC_ASSERT_SIZE(ChainConstants, 16);

// write_pattern: push constants, a constant buffer, a structured input and three outputs
// (structured, raw, storage texture), each element a value the CPU can predict.
struct WritePatternPush {
    uint count; // elements of the structured and raw buffers
    uint seed;
    uint width; // of the storage texture
    uint height;
};
LUMINA_STATIC_ASSERT_SIZE(WritePatternPush, 16);

struct WritePatternConstants {
    uint4 multiplier;   // structured output = input * multiplier + (seed, i, 7, 1)
    float elementScale; // structured .b.z = i * elementScale
    float texelW;       // the storage texture's .w
    float pad0;
    float pad1;
};
LUMINA_STATIC_ASSERT_SIZE(WritePatternConstants, 32);
LUMINA_STATIC_ASSERT_OFFSET(WritePatternConstants, elementScale, 16);

struct PatternElement {
    uint4 a;
    float4 b;
};
LUMINA_STATIC_ASSERT_SIZE(PatternElement, 32);

// mrt: vertices pulled by SV_VertexID; every attribute is flat so outputs are exact.
struct MrtVertex {
    float4 position; // clip space, w = 1
    float4 color;    // -> target 0 (RGBA8) as is, target 1 (RGBA16F) times tint
    float4 id;       // x -> target 2 (R32F)
};
LUMINA_STATIC_ASSERT_SIZE(MrtVertex, 48);

struct MrtPush {
    float4 tint;
};
LUMINA_STATIC_ASSERT_SIZE(MrtPush, 16);

// sample_texture: one result per probe.
struct SampleResult {
    float4 sampled2D;  // SampleLevel of the 2D texture at texel `probe`'s centre
    float4 loaded2D;   // Load of the same texel
    float4 arrayLayer; // Load of texel (0,0) of layer `probe % layers` of the 2D array
    float4 cubeFace;   // SampleLevel of the cube along face `probe % 6`'s axis
};
LUMINA_STATIC_ASSERT_SIZE(SampleResult, 64);

struct SampleConstants {
    uint width; // of the 2D texture
    uint height;
    uint layers; // of the 2D array
    uint count;  // probes
};
LUMINA_STATIC_ASSERT_SIZE(SampleConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
