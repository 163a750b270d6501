#include "gi/surface_cache/card_capture_pass.h"

#include "gi/surface_cache/surface_cards.h"
#include "shaders/surface_cache/card_capture_shared.h"

#include <stdexcept>
#include <string>

namespace lumina::surface_cache {
namespace {

constexpr const char* kPassName = "surface cache: card capture";
constexpr const char* kOccluderPassName = "surface cache: card occluders";

// Each instance's world box: the union of its cards' padded bounds, current after moves.
std::vector<scene::Bounds> instanceBounds(std::span<const gpu::SurfaceCard> cards, size_t instanceCount) {
    std::vector<scene::Bounds> bounds(instanceCount);
    for (const gpu::SurfaceCard& card : cards) {
        const uint32_t instance = gpu::asuint(card.boundsMaxAndInstance.w);
        if (instance < instanceCount) {
            bounds[instance].extend(cardBounds(card));
        }
    }
    return bounds;
}

} // namespace

CardCapturePass::CardCapturePass(rhi::IDevice& device, const scene::Scene& scene,
                                 const gi::GpuScene& gpuScene, const SurfaceCacheAtlas& atlas)
    : gpuScene_(gpuScene), instanceDraws_(scene.instances.size()) {
    for (const gi::SceneDraw& draw : gpuScene.draws()) {
        instanceDraws_.at(draw.constants.instance).push_back(draw);
    }
    depth_ = device.createTexture({.format = rhi::Format::D32_FLOAT,
                                   .width = atlas.size(),
                                   .height = atlas.size(),
                                   .usage = rhi::TextureUsage::DepthStencil | rhi::TextureUsage::Sampled,
                                   .debugName = "surface cache capture depth"});
}

void CardCapturePass::record(gi::FrameContext& frame, const SurfaceCacheAtlas& atlas,
                             const rhi::BufferHandle& cardBuffer, std::span<const gpu::SurfaceCard> cards,
                             std::span<const uint32_t> capture) const {
    gi::RasterPipelineState clearState;
    clearState.raster.cullMode = rhi::CullMode::None;
    clearState.depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Always};
    // Both windings: the card may see a surface from either side, and mirrored instances flip
    // the winding; the depth test keeps the nearest.
    gi::RasterPipelineState captureState = clearState;
    captureState.depth.compareOp = rhi::CompareOp::Less;
    // Occluders: other instances drawn after the card's own, depth-tested against it without
    // writing depth, clearing every texel they cover in front of the card's surface.
    gi::RasterPipelineState occluderState = captureState;
    occluderState.depth.writeEnable = false;
    const std::vector<scene::Bounds> instanceBox = instanceBounds(cards, instanceDraws_.size());
    const AtlasLayerView albedo = atlas.layer(AtlasLayer::Albedo);
    const AtlasLayerView normal = atlas.layer(AtlasLayer::Normal);
    const AtlasLayerView material = atlas.layer(AtlasLayer::Material);

    for (uint32_t index : capture) {
        if (index >= cards.size()) {
            throw std::out_of_range("card capture: card " + std::to_string(index) + " of " +
                                    std::to_string(cards.size()));
        }
        const gpu::SurfaceCard& card = cards[index];
        const uint32_t instance = gpu::asuint(card.boundsMaxAndInstance.w);
        if (instance >= instanceDraws_.size()) {
            throw std::out_of_range("card capture: card " + std::to_string(index) + " names instance " +
                                    std::to_string(instance) + " of " +
                                    std::to_string(instanceDraws_.size()));
        }
        const glm::uvec4 rect = card.atlasRect;
        if (rect.z == 0 || rect.w == 0 || rect.x + rect.z > atlas.size() || rect.y + rect.w > atlas.size()) {
            throw std::invalid_argument(
                "card capture: card " + std::to_string(index) + " has atlas rectangle " +
                std::to_string(rect.z) + "x" + std::to_string(rect.w) + " at (" + std::to_string(rect.x) +
                ", " + std::to_string(rect.y) + ") outside the " + std::to_string(atlas.size()) + " atlas");
        }
        const rhi::Viewport viewport{.x = float(rect.x),
                                     .y = float(rect.y),
                                     .width = float(rect.z),
                                     .height = float(rect.w),
                                     .minDepth = 0.0f,
                                     .maxDepth = 1.0f};
        frame
            .raster(kPassName, "surface_cache/card_capture.clearVsMain",
                    "surface_cache/card_capture.clearPsMain")
            .state(clearState)
            .colorTarget(albedo.texture, albedo.arrayLayer)
            .colorTarget(normal.texture, normal.arrayLayer)
            .colorTarget(material.texture, material.arrayLayer)
            .depthTarget(depth_)
            .viewport(viewport)
            .draw({gi::RasterDraw{.args = {.vertexOrIndexCount = 3}}}, false);

        std::vector<gi::RasterDraw> draws;
        for (const gi::SceneDraw& draw : instanceDraws_[instance]) {
            draws.push_back(gi::RasterDraw::with(
                draw.args, gpu::CardCaptureConstants{instance, draw.constants.material, index, 0}));
        }
        // The card's three layers, its depth and rectangle, and the instances' geometry.
        const auto intoCard = [&](gi::RasterPass& pass) -> gi::RasterPass& {
            return pass.read(0, gpuScene_.vertices)
                .read(1, gpuScene_.instances)
                .read(4, cardBuffer)
                .colorTarget(albedo.texture, albedo.arrayLayer)
                .colorTarget(normal.texture, normal.arrayLayer)
                .colorTarget(material.texture, material.arrayLayer)
                .depthTarget(depth_)
                .viewport(viewport)
                .indexBuffer(gpuScene_.indices);
        };
        intoCard(
            frame.raster(kPassName, "surface_cache/card_capture.vsMain", "surface_cache/card_capture.psMain")
                .state(captureState)
                .read(2, gpuScene_.materials)
                .read(3, gpuScene_.textures)
                .sampler(0, gpuScene_.materialSampler))
            .draw(draws, true);

        // A texel that another instance covers within the card's slab is hidden along the card's
        // normal, so it holds no light anyone sees from there: the emissive quad 0.1 mm under the
        // Cornell box's ceiling hid 4% of the ceiling's card, whose unlit texels then shared the
        // light's voxels and dimmed it to 65% in the voxel lighting (docs/surface_cache.md).
        std::vector<gi::RasterDraw> occluders;
        for (uint32_t other = 0; other < instanceDraws_.size(); ++other) {
            if (other == instance || !instanceBox[other].overlaps(cardBounds(card))) {
                continue;
            }
            for (const gi::SceneDraw& draw : instanceDraws_[other]) {
                occluders.push_back(gi::RasterDraw::with(
                    draw.args, gpu::CardCaptureConstants{other, draw.constants.material, index, 0}));
            }
        }
        if (occluders.empty()) {
            continue;
        }
        intoCard(frame
                     .raster(kOccluderPassName, "surface_cache/card_capture.vsMain",
                             "surface_cache/card_capture.clearPsMain")
                     .state(occluderState))
            .draw(occluders, true);
    }
}

} // namespace lumina::surface_cache
