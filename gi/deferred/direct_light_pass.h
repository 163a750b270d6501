#pragma once
// Direct lighting (shaders/deferred/direct_light.hlsl): emission plus every light's Lambert
// diffuse times its shadow visibility (sun: 3x3 PCF on the sun map; point and spot: 3x3 PCF on
// the light's cube face), per pixel of the GBuffer, into linear radiance (RGBA16F).
#include "gi/core/frame_context.h"
#include "gi/deferred/gbuffer_pass.h"

namespace lumina::gi {

struct DirectLightInputs {
    const GBuffer& gbuffer;
    rhi::BufferHandle frameConstants;   // DeferredFrameConstants
    rhi::BufferHandle shadowConstants;  // DeferredShadowConstants
    rhi::BufferHandle lights;           // DeferredLight[], at least one element
    rhi::TextureHandle sunShadowMap;    // D32
    rhi::TextureHandle pointShadowMaps; // R32F cube array
    rhi::TextureHandle sky;             // the GpuScene's sky: what pixels without a surface show
};

class DirectLightPass {
public:
    // Timed as `passName` (another view's GBuffer, a probe's cube face, times apart).
    void record(FrameContext& frame, const DirectLightInputs& inputs, const rhi::TextureHandle& direct,
                std::string_view passName = "direct light") const;
};

} // namespace lumina::gi
