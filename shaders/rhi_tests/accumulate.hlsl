// lumina-kernel: cs main
// lumina-no-dxbc: vkd3d-shader 2.1's HLSL compiler has no RWByteAddressBuffer.Load (raw UAV reads)
// Read-modify-write of one buffer, for UAV -> UAV chains: data[i] += addend + i.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"
#include "rhi_tests/rhi_tests_shared.h"

LUMINA_PUSH_CONSTANTS(ChainConstants, gChain);
RWByteAddressBuffer gData : register(u0);

static const uint kBytesPerElement = 4;

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x < gChain.count) {
        const uint address = id.x * kBytesPerElement;
        gData.Store(address, gData.Load(address) + gChain.addend + id.x);
    }
}
