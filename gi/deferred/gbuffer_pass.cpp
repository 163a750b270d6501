#include "gi/deferred/gbuffer_pass.h"

namespace lumina::gi {

GBuffer GBuffer::create(rhi::IDevice& device, uint32_t width, uint32_t height) {
    const auto target = [&](rhi::Format format, const char* name) {
        return device.createTexture({.format = format,
                                     .width = width,
                                     .height = height,
                                     .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                     .debugName = name});
    };
    GBuffer gbuffer;
    gbuffer.albedo = target(rhi::Format::RGBA8_UNORM, "gbuffer albedo");
    gbuffer.normal = target(rhi::Format::RGBA16_FLOAT, "gbuffer normal");
    gbuffer.material = target(rhi::Format::RGBA32_FLOAT, "gbuffer material");
    gbuffer.position = target(rhi::Format::RGBA32_FLOAT, "gbuffer position");
    gbuffer.depth =
        device.createTexture({.format = rhi::Format::D32_FLOAT,
                              .width = width,
                              .height = height,
                              .usage = rhi::TextureUsage::DepthStencil | rhi::TextureUsage::Sampled,
                              .debugName = "gbuffer depth"});
    return gbuffer;
}

GBufferPass::GBufferPass(const scene::Scene& scene, const GpuScene& gpuScene)
    : gpuScene_(gpuScene), groups_(gbufferDrawGroups(scene, gpuScene.draws())) {}

void GBufferPass::record(FrameContext& frame, const GBuffer& gbuffer, const rhi::BufferHandle& frameConstants,
                         std::string_view passName) const {
    rhi::ICommandList& commands = frame.commands();
    for (const rhi::TextureHandle& target :
         {gbuffer.albedo, gbuffer.normal, gbuffer.material, gbuffer.position}) {
        commands.clearColor(*target, {0.0f, 0.0f, 0.0f, 0.0f});
    }
    commands.clearDepth(*gbuffer.depth, 1.0f);
    // One raster pass per cull mode; the timing table sums them under one name.
    for (const GBufferDrawGroup& group : groups_) {
        RasterPipelineState state;
        state.raster.cullMode = group.cull;
        state.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less};
        frame.raster(passName, "deferred/gbuffer.vsMain", "deferred/gbuffer.psMain")
            .state(state)
            .constantBuffer(0, frameConstants)
            .read(0, gpuScene_.vertices)
            .read(1, gpuScene_.instances)
            .read(2, gpuScene_.materials)
            .read(3, gpuScene_.textures)
            .sampler(0, gpuScene_.materialSampler)
            .colorTarget(gbuffer.albedo)
            .colorTarget(gbuffer.normal)
            .colorTarget(gbuffer.material)
            .colorTarget(gbuffer.position)
            .depthTarget(gbuffer.depth)
            .indexBuffer(gpuScene_.indices)
            .draw(group.draws, true);
    }
}

} // namespace lumina::gi
