#include "gi/deferred/point_shadow_pass.h"

#include "shaders/deferred/deferred_shared.h"

#include <algorithm>
#include <limits>
#include <string>

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

bool PointShadowPass::allocate(uint32_t cubes) {
    if (cubes <= allocatedCubes_) {
        return false;
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
    return true;
}

void PointShadowPass::renderCube(FrameContext& frame, uint32_t cube,
                                 const rhi::BufferHandle& shadowConstants) {
    RasterPipelineState clear;
    clear.raster.cullMode = rhi::CullMode::None;
    clear.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Always};
    RasterPipelineState casters;
    casters.raster.cullMode = rhi::CullMode::None; // both faces cast
    casters.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less};
    const std::vector<RasterDraw> cover{RasterDraw{.args = {.vertexOrIndexCount = 3}}};
    for (uint32_t face = 0; face < LUMINA_CUBE_FACE_COUNT; ++face) {
        const uint32_t layer = cube * LUMINA_CUBE_FACE_COUNT + face;
        frame.raster(kPassName, "deferred/shadow_layer_clear.vsMain", "deferred/shadow_layer_clear.psMain")
            .state(clear)
            .colorTarget(distance_, layer)
            .depthTarget(depth_, layer)
            .draw(cover, false);
        frame.raster(kPassName, "deferred/point_shadow.vsMain", "deferred/point_shadow.psMain")
            .state(casters)
            .constantBuffer(1, shadowConstants)
            .read(0, gpuScene_.vertices)
            .read(1, gpuScene_.instances)
            .colorTarget(distance_, layer)
            .depthTarget(depth_, layer)
            .indexBuffer(gpuScene_.indices)
            .draw(shadowRasterDraws(draws_, layer), true);
    }
}

std::vector<bool> PointShadowPass::record(FrameContext& frame, const std::vector<glm::vec4>& cubes,
                                          const rhi::BufferHandle& shadowConstants,
                                          std::span<const scene::Bounds> movedRegions) {
    rhi::ICommandList& commands = frame.commands();
    if (!placeholderCleared_) {
        commands.clearColor(*placeholder_, kFarDistance);
        placeholderCleared_ = true;
    }
    std::vector<bool> rendered(cubes.size(), false);
    cubeCount_ = static_cast<uint32_t>(cubes.size());
    if (cubes.empty()) {
        frame.skip(kPassName, "no point or spot lights");
        return rendered;
    }
    const bool fresh = allocate(cubeCount_);
    renderedCubes_.resize(cubes.size(), glm::vec4(std::numeric_limits<float>::quiet_NaN()));
    renderedFrames_.resize(cubes.size(), 0);
    std::vector<std::string> kept;
    for (uint32_t cube = 0; cube < cubes.size(); ++cube) {
        const glm::vec4& sphere = cubes[cube];
        // A moved box within the range sphere can change what this cube sees.
        const bool geometryInRange =
            std::any_of(movedRegions.begin(), movedRegions.end(), [&](const scene::Bounds& box) {
                const glm::vec3 nearest = glm::clamp(glm::vec3(sphere), box.min, box.max);
                return !box.empty() && glm::distance(nearest, glm::vec3(sphere)) <= sphere.w;
            });
        const bool unchanged = !fresh && sphere == renderedCubes_[cube] && !geometryInRange;
        if (unchanged && frame.mayReuse(kPassName)) {
            kept.push_back(std::to_string(cube) + " (since frame " + std::to_string(renderedFrames_[cube]) +
                           ")");
            continue;
        }
        renderCube(frame, cube, shadowConstants);
        // Forced (lumina bench --verify-skips) over an unchanged cube: the same distances again,
        // which must not read as a change, or the surface cache would re-light and restart its
        // bounces around the light.
        if (unchanged) {
            continue;
        }
        renderedCubes_[cube] = sphere;
        renderedFrames_[cube] = frame.frameIndex();
        rendered[cube] = true;
    }
    if (kept.size() == cubes.size()) {
        const uint64_t last = *std::max_element(renderedFrames_.begin(), renderedFrames_.end());
        frame.skipReused(kPassName, "unchanged since frame " + std::to_string(last));
    } else if (!kept.empty()) {
        std::string list;
        for (const std::string& k : kept) {
            list += (list.empty() ? "" : ", ") + k;
        }
        frame.skipReused(std::string(kPassName) + ": unchanged cubes", list);
    }
    return rendered;
}

} // namespace lumina::gi
