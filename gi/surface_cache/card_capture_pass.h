#pragma once
// Card capture: re-renders dirty cards into the atlas (shaders/surface_cache/card_capture.hlsl).
// Each card's instance is drawn orthographically along the card's normal, its world-to-card map
// as the projection and its atlas rectangle as the viewport, writing albedo, world normal and
// material in one multi-render-target pass; a full-rectangle draw first resets the texels and
// the depth. Then the other instances whose bounds meet the card's are drawn depth-tested, not
// depth-written ("card occluders"), resetting the texels they hide within the card's slab: what
// another surface covers along the card's normal is seen by nobody from that side, and left in,
// it dimmed whatever covered it in the voxel lighting. Cards never share texels, so one
// atlas-sized depth buffer serves every card and needs no clear of its own.
#include "gi/core/frame_context.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "gi/surface_cache/surface_cache_atlas.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <span>
#include <vector>

namespace lumina::surface_cache {

class CardCapturePass {
public:
    CardCapturePass(rhi::IDevice& device, const scene::Scene& scene, const gi::GpuScene& gpuScene,
                    const SurfaceCacheAtlas& atlas);

    // Captures cards[i] for every i in `capture`; cardBuffer holds `cards` on the GPU
    // (StructuredBuffer<SurfaceCard>). The caller clears DIRTY (SurfaceCards::markCaptured)
    // once the frame is submitted. Throws std::out_of_range for a card or instance index past
    // the end, std::invalid_argument for a rectangle outside the atlas.
    void record(gi::FrameContext& frame, const SurfaceCacheAtlas& atlas, const rhi::BufferHandle& cardBuffer,
                std::span<const gpu::SurfaceCard> cards, std::span<const uint32_t> capture) const;

    // The atlas-sized D32 depth of the captures: card-space z of each captured texel (sampled
    // by the lighting passes to find a texel's world position).
    const rhi::TextureHandle& depth() const { return depth_; }

private:
    const gi::GpuScene& gpuScene_;
    std::vector<std::vector<gi::SceneDraw>> instanceDraws_; // per instance: its submeshes
    rhi::TextureHandle depth_;                              // D32, atlas-sized
};

} // namespace lumina::surface_cache
