// lumina-kernel: cs main
// A link of the barrier-chain tests: reads what the previous dispatch wrote.
// out[i] = in[i] * multiplier + addend.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "rhi_tests/rhi_tests_shared.h"

LUMINA_PUSH_CONSTANTS(ChainConstants, gChain);
StructuredBuffer<uint> gInput : register(t0);
RWStructuredBuffer<uint> gOutput : register(u0);

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x < gChain.count) {
        gOutput[id.x] = gInput[id.x] * gChain.multiplier + gChain.addend;
    }
}
