#pragma once
// The whole surface cache of a scene: cards, atlas and the passes that light it. update()
// records one update per frame:
//
//   capture dirty cards ─► combine ─► voxel inject ─► radiosity (one bounce, within a budget)
//
// Combine and voxel lighting run while something they read changed (a capture, or the last
// update's radiosity); radiosity runs until converged and restarts when a light or object
// moves. Every pass that does not run records why (frame.skip). The direct-light layer is not
// written yet (docs/surface_cache.md): it stays zero, so emission is the only light source.
//
//   SurfaceCache cache(device, scene, gpuScene, sceneSdf, settings);
//   cache.update(frame);                      // every frame, after sceneSdf.record(frame)
//   cache.moveInstance(3, transform, lights); // and sceneSdf.setInstanceTransform(3, transform)
#include "gi/core/frame_context.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/atlas_tile_list.h"
#include "gi/surface_cache/card_bvh.h"
#include "gi/surface_cache/card_capture_pass.h"
#include "gi/surface_cache/radiosity_pass.h"
#include "gi/surface_cache/radiosity_schedule.h"
#include "gi/surface_cache/surface_cache_atlas.h"
#include "gi/surface_cache/surface_cache_combine_pass.h"
#include "gi/surface_cache/surface_cache_direct_light_pass.h"
#include "gi/surface_cache/surface_cards.h"
#include "gi/surface_cache/tile_owner_texture.h"
#include "gi/surface_cache/voxel_lighting_pass.h"

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

namespace lumina::surface_cache {

struct SurfaceLightingSettings {
    uint32_t voxelResolution = 64; // voxel lighting: voxels per side over the scene bounds
    RadiosityTraceSettings trace;
    RadiosityScheduleSettings schedule;
};

class SurfaceCache {
public:
    static constexpr const char* kCapturePassName = "surface cache: card capture";

    // Keeps references to gpuScene and sdf (they must outlive the cache). Throws what
    // SurfaceCards, SurfaceCacheAtlas and the passes throw for bad settings (a full atlas
    // degrades the cards' levels instead, surface_cards.h).
    SurfaceCache(rhi::IDevice& device, const scene::Scene& scene, const gi::GpuScene& gpuScene,
                 const sdf::SceneSdf& sdf, const SurfaceCacheSettings& settings,
                 const SurfaceLightingSettings& lighting = {});

    // Records one update, lit by `lights` (the deferred renderer's, after its render() this
    // frame), or by emission alone without them. With a `viewer` (the camera's position) that
    // moved, the cards' levels of detail follow it first (SurfaceCards::updateLod). The first
    // update captures every card, later ones at most capturesPerFrame (most useful first). The
    // cards it captures count as captured once it returns: submit the frame's commands.
    void update(gi::FrameContext& frame, const std::optional<gi::ShadowedLights>& lights = std::nullopt,
                const std::optional<glm::vec3>& viewer = std::nullopt);
    // The cards' levels follow `viewer` now rather than at the next update() (which then does not
    // plan them again), so that updateIsComputeOnly() sees the captures a new plan asks for.
    void planLod(const std::optional<glm::vec3>& viewer);
    // True when the next update() with `lights` would record compute work only and read nothing
    // the frame's raster wrote: no card to capture (a raster pass), no card to light again (that
    // reads shadow maps rendered this frame). Such an update may go on the async compute queue
    // (FrameRenderer::render with a SplitFrame). Call planLod() first.
    bool updateIsComputeOnly(const std::optional<gi::ShadowedLights>& lights) const;

    // An instance moved: its cards are placed anew and captured at the next update, with the
    // cards it overlapped before or overlaps now; radiosity restarts within one ray's reach of
    // its old and new boxes.
    void moveInstance(uint32_t instance, const glm::mat4& transform, std::span<const scene::Light> lights);
    // The scene's lights are now `lights`, as DeferredRenderer::setLights gave them version
    // `lightsVersion` (so the update that sees that version knows what changed): light masks are
    // recomputed, only the cards a changed light reached before or reaches now are lit again, and
    // radiosity restarts within one ray's reach of them. Without this call a new lights version
    // re-lights every card.
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion);
    // The cards of `instance` are captured again (a material it draws changed: emission), and
    // radiosity restarts near them.
    void instanceMaterialChanged(uint32_t instance);
    // A light changed: radiosity restarts.
    void lightsChanged();

    // Every texel of a layer as linear RGBA floats, row-major (waits for the GPU). For
    // --dump-buffers and tests.
    std::vector<glm::vec4> readLayer(AtlasLayer layer) const;
    // Every voxel face of the voxel lighting: rows of LUMINA_VOXEL_FACES x dims.x texels (face f
    // of voxel x at f * dims.x + x), then y, then z.
    std::vector<glm::vec4> readVoxelLighting() const;

    const SurfaceCards& cards() const { return cards_; }
    // The card LOD's work so far: the last update's changes, and evictions over all updates.
    struct LodHistory {
        CardLodUpdate last;
        uint64_t updates = 0;   // updates that re-planned the levels
        uint64_t evictions = 0; // cards evicted by those updates
        uint32_t maxEvictionsPerUpdate = 0;
        uint32_t pendingCaptures = 0; // dirty cards the last update's capture budget left
    };
    const LodHistory& lodHistory() const { return lodHistory_; }
    // Radiosity has converged and no dirty card waits for its capture.
    bool settled() const { return schedule_.converged() && lodHistory_.pendingCaptures == 0; }
    const SurfaceCacheAtlas& atlas() const { return atlas_; }
    const VoxelLightingPass& voxelLighting() const { return voxels_; }
    const RadiositySchedule& radiositySchedule() const { return schedule_; }
    const RadiosityPass& radiosity() const { return radiosity_; }
    // The tiles that hold cards, row-major atlas tile indices.
    const std::vector<uint32_t>& cardTiles() const { return cardTiles_; }
    const CardCapturePass& capture() const { return capture_; }
    // The R32_UINT tile-to-card lookup (TileOwnerTexture), current once update() has run.
    const rhi::TextureHandle& tileOwner() const { return tileOwner_.texture(); }
    // The cards and their BVH on the GPU (StructuredBuffer<SurfaceCard>, <CardBvhNode>), current
    // once update() has run since the last move: what SDF hits outside the cache read to find
    // their card (shaders/surface_cache/card_bvh_traversal.hlsli).
    const rhi::BufferHandle& cardBuffer() const { return cardBuffer_; }
    const rhi::BufferHandle& cardBvhBuffer() const { return cardBvhBuffer_; }
    const CardBvh& cardBvh() const { return cardBvh_; }

private:
    void updateLod(const glm::vec3& viewer);
    void uploadCards(rhi::ICommandList& commands);
    // Radiosity starts over on the tiles of cards within a ray's reach of `regions`.
    void restartRadiosityNear(std::span<const scene::Bounds> regions);
    // The union of an instance's (padded) card bounds as placed now.
    scene::Bounds instanceCardBounds(uint32_t instance) const;
    // Records the direct light where it is stale; true when it ran.
    bool recordDirectLight(gi::FrameContext& frame, const std::optional<gi::ShadowedLights>& lights,
                           const std::vector<uint32_t>& capturedTiles);

    rhi::IDevice& device_;
    SurfaceCards cards_;
    SurfaceCacheAtlas atlas_;
    CardCapturePass capture_;
    TileOwnerTexture tileOwner_;
    rhi::BufferHandle cardBuffer_;
    AtlasTileList allTiles_;       // every tile that holds a card: combine and voxel inject
    AtlasTileList radiosityTiles_; // the schedule's pick
    AtlasTileList directTiles_;    // tiles whose direct light is stale
    SurfaceCacheDirectLightPass directLight_;
    SurfaceCacheCombinePass combine_;
    VoxelLightingPass voxels_;
    RadiosityPass radiosity_;
    RadiositySchedule schedule_;
    std::vector<uint32_t> cardTiles_;
    CardBvh cardBvh_; // rebuilt on moves, uploaded with the cards
    rhi::BufferHandle cardBvhBuffer_;
    LodHistory lodHistory_;
    std::optional<glm::vec3> lodViewer_; // where the levels were last planned from
    bool lodPlanned_ = false;            // planLod ran since the last update
    bool initialised_ = false;           // the first update clears every layer and buffer
    bool cardsChanged_ = true;           // card buffer and tile-to-card lookup need an upload
    bool indirectChanged_ = false;       // radiosity wrote the indirect layer after the last combine
    uint32_t updates_ = 0;
    // What the direct layer was computed with: the lights' version (none before the first) and,
    // per light, the frame of the shadow map it read (ShadowedLights::shadowFrames).
    std::optional<uint64_t> directLightsVersion_;
    std::vector<uint64_t> directShadowFrames_;
    std::vector<scene::Light> lights_;               // as of the last setLights
    std::optional<uint64_t> announcedLightsVersion_; // the version setLights announced
    std::vector<uint32_t> relightCards_;             // cards a changed light reaches
};

} // namespace lumina::surface_cache
