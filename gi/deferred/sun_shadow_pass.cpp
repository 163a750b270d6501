#include "gi/deferred/sun_shadow_pass.h"

namespace lumina::gi {

namespace {

rhi::TextureHandle createDepthMap(rhi::IDevice& device, uint32_t size, const char* name) {
    return device.createTexture({.format = rhi::Format::D32_FLOAT,
                                 .width = size,
                                 .height = size,
                                 .usage = rhi::TextureUsage::DepthStencil | rhi::TextureUsage::Sampled,
                                 .debugName = name});
}

} // namespace

SunShadowPass::SunShadowPass(rhi::IDevice& device, const GpuScene& gpuScene, uint32_t mapSize)
    : device_(device), gpuScene_(gpuScene), mapSize_(mapSize), draws_(shadowDraws(gpuScene.draws())),
      placeholder_(createDepthMap(device, 1, "sun shadow map (none)")) {}

bool SunShadowPass::record(FrameContext& frame, const std::optional<SunShadowFit>& fit,
                           const rhi::BufferHandle& shadowConstants, bool geometryMoved) {
    if (!placeholderCleared_) {
        frame.commands().clearDepth(*placeholder_, 1.0f);
        placeholderCleared_ = true;
    }
    if (!fit) {
        valid_ = false;
        frame.skip(kPassName, "no directional light");
        return false;
    }
    const bool unchanged = valid_ && fit->viewProjRows == renderedRows_ && !geometryMoved;
    if (unchanged && frame.mayReuse(kPassName)) {
        frame.skipReused(kPassName, "unchanged since frame " + std::to_string(renderedFrame_));
        return false;
    }
    if (!map_) {
        map_ = createDepthMap(device_, mapSize_, "sun shadow map");
    }
    frame.commands().clearDepth(*map_, 1.0f);
    RasterPipelineState state;
    state.raster.cullMode = rhi::CullMode::None; // both faces cast (single-sided walls included)
    state.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less};
    frame.raster(kPassName, "deferred/sun_shadow.vsMain", "")
        .state(state)
        .constantBuffer(1, shadowConstants)
        .read(0, gpuScene_.vertices)
        .read(1, gpuScene_.instances)
        .depthTarget(map_)
        .indexBuffer(gpuScene_.indices)
        .draw(shadowRasterDraws(draws_, 0), true);
    // Forced (lumina bench --verify-skips) over an unchanged map: the same depths again, which
    // must not read as a change, or the surface cache would re-light and restart its bounces.
    if (unchanged) {
        return false;
    }
    valid_ = true;
    renderedRows_ = fit->viewProjRows;
    renderedFrame_ = frame.frameIndex();
    return true;
}

} // namespace lumina::gi
