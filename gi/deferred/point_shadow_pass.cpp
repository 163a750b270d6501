#include "gi/deferred/point_shadow_pass.h"

#include "shaders/deferred/deferred_shared.h"

namespace lumina::gi {

namespace {

rhi::TextureHandle createDistanceCubes(rhi::IDevice& device, uint32_t size, uint32_t cubes,
                                       const char* name) {
    return device.createTexture({.dimension = rhi::TextureDimension::TextureCubeArray,
                                 .format = rhi::Format::R32_FLOAT,
                                 .width = size,
                                 .height = size,
                                 .arrayLayers = cubes * LUMINA_CUBE_FACE_COUNT,
                                 .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                 .debugName = name});
}

// Cleared to 1: as far as the shadow range, so nothing is shadowed where nothing was drawn.
constexpr std::array<float, 4> kFarDistance{1.0f, 1.0f, 1.0f, 1.0f};

} // namespace

PointShadowPass::PointShadowPass(rhi::IDevice& device, const GpuScene& gpuScene, uint32_t faceSize)
    : device_(device), gpuScene_(gpuScene), faceSize_(faceSize), draws_(shadowDraws(gpuScene.draws())),
      placeholder_(createDistanceCubes(device, 1, 1, "point shadow maps (none)")) {}

void PointShadowPass::allocate(uint32_t cubes) {
    if (cubes <= allocatedCubes_) {
        return;
    }
    distance_ = createDistanceCubes(device_, faceSize_, cubes, "point shadow maps");
    depth_ = device_.createTexture({.dimension = rhi::TextureDimension::Texture2DArray,
                                    .format = rhi::Format::D32_FLOAT,
                                    .width = faceSize_,
                                    .height = faceSize_,
                                    .arrayLayers = cubes * LUMINA_CUBE_FACE_COUNT,
                                    .usage = rhi::TextureUsage::DepthStencil,
                                    .debugName = "point shadow depth"});
    allocatedCubes_ = cubes;
}

void PointShadowPass::record(FrameContext& frame, const std::vector<glm::vec4>& cubes,
                             const rhi::BufferHandle& shadowConstants, uint64_t geometryVersion) {
    rhi::ICommandList& commands = frame.commands();
    if (!placeholderCleared_) {
        commands.clearColor(*placeholder_, kFarDistance);
        placeholderCleared_ = true;
    }
    if (cubes.empty()) {
        cubeCount_ = 0;
        frame.skip("point shadows", "no point or spot lights");
        return;
    }
    if (cubeCount_ == cubes.size() && cubes == renderedCubes_ && geometryVersion == renderedGeometry_) {
        frame.skip("point shadows", "unchanged since frame " + std::to_string(renderedFrame_));
        return;
    }
    allocate(static_cast<uint32_t>(cubes.size()));
    commands.clearColor(*distance_, kFarDistance);
    commands.clearDepth(*depth_, 1.0f);
    RasterPipelineState state;
    state.raster.cullMode = rhi::CullMode::None; // both faces cast
    state.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less};
    for (uint32_t layer = 0; layer < cubes.size() * LUMINA_CUBE_FACE_COUNT; ++layer) {
        frame.raster("point shadows", "deferred/point_shadow.vsMain", "deferred/point_shadow.psMain")
            .state(state)
            .constantBuffer(1, shadowConstants)
            .read(0, gpuScene_.vertices)
            .read(1, gpuScene_.instances)
            .colorTarget(distance_, layer)
            .depthTarget(depth_, layer)
            .indexBuffer(gpuScene_.indices)
            .draw(shadowRasterDraws(draws_, layer), true);
    }
    cubeCount_ = static_cast<uint32_t>(cubes.size());
    renderedCubes_ = cubes;
    renderedGeometry_ = geometryVersion;
    renderedFrame_ = frame.frameIndex();
}

} // namespace lumina::gi
