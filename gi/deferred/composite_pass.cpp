#include "gi/deferred/composite_pass.h"

#include "shaders/deferred/deferred_shared.h"

#include <cmath>

namespace lumina::gi {

CompositePass::CompositePass(rhi::IDevice& device)
    : black_(device.createTexture({.format = rhi::Format::RGBA16_FLOAT,
                                   .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                   .debugName = "no indirect light"})) {}

void CompositePass::record(FrameContext& frame, const CompositeInputs& inputs, const rhi::TextureHandle& hdr,
                           const rhi::TextureHandle& ldr) {
    if (!blackCleared_) {
        frame.commands().clearColor(*black_, {0.0f, 0.0f, 0.0f, 0.0f});
        blackCleared_ = true;
    }
    const rhi::TextureDesc& size = hdr->desc();
    const gpu::CompositeConstants constants{size.width,
                                            size.height,
                                            inputs.indirect ? LUMINA_DEFERRED_FLAG_INDIRECT : 0u,
                                            std::exp2(inputs.exposureEv),
                                            inputs.indirectScale,
                                            0.0f,
                                            0.0f,
                                            0.0f};
    frame.compute("composite", "deferred/composite")
        .constants(constants)
        .read(0, inputs.direct)
        .read(1, inputs.indirect ? inputs.indirect : black_)
        .read(2, inputs.albedo)
        .write(0, hdr)
        .write(1, ldr)
        .dispatchThreads(size.width, size.height, {LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE});
}

} // namespace lumina::gi
