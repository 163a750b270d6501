#pragma once
// The scene's draws, grouped the way the raster passes need them. The GBuffer culls back
// faces as glTF says: single-sided materials cull the back face, double-sided ones draw both,
// and a mirroring instance (negative determinant) turns its front faces clockwise, so it
// culls the other winding. Shadow maps draw every triangle from both sides.
#include "gi/core/frame_context.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "shaders/deferred/deferred_shared.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lumina::gi {

struct GBufferDrawGroup {
    rhi::CullMode cull = rhi::CullMode::Back;
    std::vector<RasterDraw> draws; // push constants: gpu::GBufferVisibilityDrawConstants
};

// The visibility raster's draws and the table its resolve finds them in. Triangle ids run over
// the draws in drawing order from 1, so the table is sorted by firstId.
struct GBufferDraws {
    std::vector<GBufferDrawGroup> groups; // non-empty only, in the order cull back, front, none
    std::vector<gpu::GBufferResolveDraw> resolveTable;
    uint64_t triangleCount = 0;
};
GBufferDraws gbufferDraws(const scene::Scene& scene, std::span<const SceneDraw> draws);

// One indexed range per instance where its submeshes are contiguous in the index buffer.
struct ShadowDraw {
    rhi::DrawArgs args;
    uint32_t instance = 0;
};
std::vector<ShadowDraw> shadowDraws(std::span<const SceneDraw> draws);

// The shadow draws with push constants gpu::ShadowDrawConstants for one array layer.
std::vector<RasterDraw> shadowRasterDraws(const std::vector<ShadowDraw>& draws, uint32_t layer);

} // namespace lumina::gi
