// lumina-kernel: cs main
// First link of the barrier-chain tests: out[i] = i * multiplier + addend.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "rhi_tests/rhi_tests_shared.h"

LUMINA_PUSH_CONSTANTS(ChainConstants, gChain);
RWStructuredBuffer<uint> gOutput : register(u0);

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x < gChain.count) {
        gOutput[id.x] = id.x * gChain.multiplier + gChain.addend;
    }
}
