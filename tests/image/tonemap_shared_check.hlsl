// Compile check (not a runtime kernel): every function of shaders/common/tonemap_shared.h
// must build as HLSL with the project's SPIR-V compiler. Run by ctest as unit.tonemap_shared_hlsl.
#include "common/tonemap_shared.h"
#include "common/tonemap_shared.h" // the include guard holds

RWStructuredBuffer<float4> gOut : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    const float3 radiance = float3(id.x * 0.25f, 0.5f, 4.0f);
    const float3 display = tonemapToDisplay3(radiance, 2.0f);
    const float scalar = tonemapToDisplay(radiance.x, 1.0f) + srgbEotf(display.y) + acesFitted(radiance.z);
    gOut[id.x] = float4(display + acesFitted3(radiance) + srgbOetf3(radiance), scalar);
}
