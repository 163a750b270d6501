#pragma once
// Composite (shaders/deferred/composite.hlsl): HDR = direct + indirect x albedo (RGBA16F),
// then exposure, the ACES fit and the sRGB OETF into the displayable image (RGBA8).
#include "gi/core/frame_context.h"

namespace lumina::gi {

struct CompositeInputs {
    rhi::TextureHandle direct;
    rhi::TextureHandle indirect; // null: no indirect term
    float indirectScale = 1.0f;  // HDR adds indirect x indirectScale x albedo (1/pi for irradiance)
    rhi::TextureHandle albedo;
    float exposureEv = 0.0f;
};

class CompositePass {
public:
    explicit CompositePass(rhi::IDevice& device);

    void record(FrameContext& frame, const CompositeInputs& inputs, const rhi::TextureHandle& hdr,
                const rhi::TextureHandle& ldr);

private:
    rhi::TextureHandle black_; // bound in place of a missing indirect texture, never read
    bool blackCleared_ = false;
};

} // namespace lumina::gi
