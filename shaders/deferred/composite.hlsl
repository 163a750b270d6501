// lumina-kernel: cs main
// Composite: HDR = direct + indirect x albedo, then the project's display transform
// (exposure, Narkowicz's ACES fit, sRGB OETF; shaders/common/tonemap_shared.h) into RGBA8.
#include "common/bindings.hlsli"
#include "common/tonemap_shared.h"
#include "deferred/deferred_shared.h"

LUMINA_PUSH_CONSTANTS(CompositeConstants, gConstants);
Texture2D<float4> gDirect : register(t0);
// Indirect light, times indirectScale and albedo: 1/pi turns the GI's irradiance E into the
// Lambertian outgoing radiance albedo x E / pi.
Texture2D<float4> gIndirect : register(t1);
Texture2D<float4> gAlbedo : register(t2);
LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gHdr : register(u0);
LUMINA_UAV_FORMAT(rgba8) RWTexture2D<float4> gLdr : register(u1);

[numthreads(LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= gConstants.width || id.y >= gConstants.height) {
        return;
    }
    const int3 pixel = int3(id.xy, 0);
    float3 hdr = gDirect.Load(pixel).rgb;
    if ((gConstants.flags & LUMINA_DEFERRED_FLAG_INDIRECT) != 0u) {
        hdr += gConstants.indirectScale * gIndirect.Load(pixel).rgb * gAlbedo.Load(pixel).rgb;
    }
    gHdr[id.xy] = float4(hdr, 1.0);
    gLdr[id.xy] = float4(tonemapToDisplay3(hdr, gConstants.exposureScale), 1.0);
}
