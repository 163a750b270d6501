// lumina-kernel: cs main
// `lumina gpu-check`: every thread writes a value the CPU can predict, proving that
// kernels compile, bind, dispatch and read back on the chosen device.
#include "common/bindings.hlsli"
#include "common/constants_shared.h"

struct GpuCheckConstants {
    uint count;
    uint seed;
    uint2 pad;
};
LUMINA_PUSH_CONSTANTS(GpuCheckConstants, gConstants);

RWStructuredBuffer<uint> gOutput : register(u0);

// Same hash as app/commands/gpu_check_command.cpp (PCG output permutation).
uint pcgHash(uint value) {
    uint state = value * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
    if (id.x < gConstants.count) {
        gOutput[id.x] = pcgHash(id.x ^ gConstants.seed);
    }
}
