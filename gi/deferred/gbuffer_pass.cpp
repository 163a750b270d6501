#include "gi/deferred/gbuffer_pass.h"

#include "rhi/transfer.h"
#include "shaders/deferred/deferred_shared.h"

#include <stdexcept>
#include <string>

namespace lumina::gi {

GBuffer GBuffer::create(rhi::IDevice& device, uint32_t width, uint32_t height) {
    const auto target = [&](rhi::Format format, const char* name) {
        return device.createTexture({.format = format,
                                     .width = width,
                                     .height = height,
                                     .usage = rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled,
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
    gbuffer.visibility =
        device.createTexture({.format = rhi::Format::R32_UINT,
                              .width = width,
                              .height = height,
                              .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                              .debugName = "gbuffer visibility"});
    return gbuffer;
}

GBufferPass::GBufferPass(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene)
    : gpuScene_(gpuScene) {
    GBufferDraws draws = gbufferDraws(scene, gpuScene.draws());
    if (draws.triangleCount > LUMINA_GBUFFER_ID_MASK) {
        throw std::runtime_error("GBuffer: the scene draws " + std::to_string(draws.triangleCount) +
                                 " triangles, more than the visibility target's ids can number (" +
                                 std::to_string(LUMINA_GBUFFER_ID_MASK) + ")");
    }
    groups_ = std::move(draws.groups);
    std::vector<gpu::GBufferResolveDraw>& table = draws.resolveTable;
    drawCount_ = uint32_t(table.size());
    if (table.empty()) {
        table.push_back({1u, 0u, 0u, 0u}); // a buffer cannot be empty; no pixel reads it
    }
    resolveDraws_ = rhi::createBufferWithData(device,
                                              {.structStride = sizeof(gpu::GBufferResolveDraw),
                                               .usage = rhi::BufferUsage::Structured,
                                               .debugName = "gbuffer resolve draws"},
                                              table.data(), table.size() * sizeof(gpu::GBufferResolveDraw));
}

void GBufferPass::record(FrameContext& frame, const GBuffer& gbuffer, const rhi::BufferHandle& frameConstants,
                         std::string_view passName) const {
    const std::string visibilityName = std::string(passName) + " visibility";
    const std::string resolveName = std::string(passName) + " resolve";
    rhi::ICommandList& commands = frame.commands();
    commands.clearColor(*gbuffer.visibility, {0.0f, 0.0f, 0.0f, 0.0f});
    commands.clearDepth(*gbuffer.depth, 1.0f);
    // One raster pass per cull mode; the timing table sums them under one name.
    for (const GBufferDrawGroup& group : groups_) {
        RasterPipelineState state;
        state.raster.cullMode = group.cull;
        state.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less};
        frame
            .raster(visibilityName, "deferred/gbuffer_visibility.vsMain",
                    "deferred/gbuffer_visibility.psMain")
            .state(state)
            .constantBuffer(0, frameConstants)
            .read(0, gpuScene_.vertices)
            .read(1, gpuScene_.instances)
            .colorTarget(gbuffer.visibility)
            .depthTarget(gbuffer.depth)
            .indexBuffer(gpuScene_.indices)
            .draw(group.draws, true);
    }
    const rhi::TextureDesc& size = gbuffer.albedo->desc();
    frame.compute(resolveName, "deferred/gbuffer_resolve")
        .constants(gpu::GBufferResolveConstants{size.width, size.height, drawCount_, 0u})
        .constantBuffer(0, frameConstants)
        .read(0, gbuffer.visibility)
        .read(1, resolveDraws_)
        .read(2, gpuScene_.indices)
        .read(3, gpuScene_.vertices)
        .read(4, gpuScene_.instances)
        .read(5, gpuScene_.materials)
        .read(6, gpuScene_.textures)
        .sampler(0, gpuScene_.materialSampler)
        .write(0, gbuffer.albedo)
        .write(1, gbuffer.normal)
        .write(2, gbuffer.material)
        .write(3, gbuffer.position)
        .dispatchThreads(size.width, size.height, {LUMINA_DEFERRED_GROUP_SIZE, LUMINA_DEFERRED_GROUP_SIZE});
}

} // namespace lumina::gi
