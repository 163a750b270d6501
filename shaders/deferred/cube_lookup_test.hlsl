// lumina-kernel: cs main
// Test kernel (tests/deferred/deferred_gpu_test.cpp): reads the point shadow maps both ways
// for each direction, through the hardware cube lookup (TextureCubeArray) and through the
// face addressing the direct-light pass uses (cubeFaceOf / cubeFaceUv on 2D array layers), so
// the test can check that the maps are laid out in the APIs' cube convention.
#include "common/bindings.hlsli"
#include "deferred/deferred_shared.h"

struct CubeLookupConstants {
    uint count;
    uint cube;
    uint faceSize;
    uint pad;
};

LUMINA_PUSH_CONSTANTS(CubeLookupConstants, gConstants);
TextureCubeArray<float> gCubes : register(t0);
Texture2DArray<float> gLayers : register(t1);
StructuredBuffer<float4> gDirections : register(t2);
SamplerState gPoint : register(s0);
RWStructuredBuffer<float4> gResults : register(u0); // x: hardware; y: face addressing; z: face

[numthreads(LUMINA_LINEAR_GROUP_SIZE, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gConstants.count) {
        return;
    }
    const float3 d = gDirections[id.x].xyz;
    const float hardware = gCubes.SampleLevel(gPoint, float4(d, float(gConstants.cube)), 0.0);
    const uint face = cubeFaceOf(d);
    const int size = int(gConstants.faceSize);
    const int2 texel = min(int2(cubeFaceUv(d, face) * float(size)), int2(size - 1, size - 1));
    const float addressed = gLayers.Load(int4(texel, int(gConstants.cube * LUMINA_CUBE_FACE_COUNT + face), 0));
    gResults[id.x] = float4(hardware, addressed, float(face), 0.0);
}
