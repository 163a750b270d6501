#include "gi/deferred/direct_light_pass.h"

#include "shaders/deferred/deferred_shared.h"

namespace lumina::gi {

void DirectLightPass::record(FrameContext& frame, const DirectLightInputs& inputs,
                             const rhi::TextureHandle& direct, std::string_view passName) const {
    // The kernel addresses cube faces itself (cubeFaceOf / cubeFaceUv) and reads them as layers.
    rhi::BindingSetItem pointMaps = rhi::BindingSetItem::sampledTexture(5, inputs.pointShadowMaps);
    pointMaps.overrideDimension = true;
    pointMaps.viewDimension = rhi::TextureDimension::Texture2DArray;
    const rhi::TextureDesc& size = direct->desc();
    frame.compute(passName, "deferred/direct_light")
        .constantBuffer(0, inputs.frameConstants)
        .constantBuffer(1, inputs.shadowConstants)
        .read(0, inputs.gbuffer.albedo)
        .read(1, inputs.gbuffer.normal)
        .read(2, inputs.gbuffer.material)
        .read(3, inputs.gbuffer.position)
        .read(4, inputs.sunShadowMap)
        .bind(pointMaps)
        .read(6, inputs.lights)
        .read(7, inputs.sky)
        .write(0, direct)
        .dispatchThreads(size.width, size.height, {LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE});
}

} // namespace lumina::gi
