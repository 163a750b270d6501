#include "gi/surface_cache/surface_cache.h"

#include <algorithm>
#include <glm/gtc/packing.hpp>
#include <limits>
#include <numeric>
#include <string>

namespace lumina::surface_cache {
namespace {

// The brightest albedo channel of any material: how slowly light dies out between bounces.
float maxAlbedo(const scene::Scene& scene) {
    float albedo = 0.0f;
    for (const scene::Material& material : scene.materials) {
        albedo = std::max({albedo, material.baseColor.r, material.baseColor.g, material.baseColor.b});
    }
    return albedo;
}

// The voxel lighting covers every card's padded bounds.
gpu::VoxelGridInfo gridOverCards(const SurfaceCards& cards, uint32_t resolution) {
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (const gpu::SurfaceCard& card : cards.cards()) {
        lo = glm::min(lo, glm::vec3(card.boundsMinAndFlags));
        hi = glm::max(hi, glm::vec3(card.boundsMaxAndInstance));
    }
    if (cards.cards().empty()) {
        lo = glm::vec3(-1.0f);
        hi = glm::vec3(1.0f); // an empty scene: any non-empty box, nothing is injected
    }
    return voxelGridOver(lo, hi, resolution);
}

std::vector<uint32_t> tilesWithCards(const TileAllocator& allocator) {
    std::vector<uint32_t> tiles;
    const std::vector<uint32_t>& owners = allocator.ownerTable();
    for (uint32_t i = 0; i < owners.size(); ++i) {
        if (owners[i] != kNoOwner) {
            tiles.push_back(i);
        }
    }
    return tiles;
}

// The atlas tiles of a card's rectangle, row-major tile indices.
void appendCardTiles(const SurfaceCards& cards, uint32_t card, std::vector<uint32_t>& tiles) {
    const glm::uvec4 rect = cards.cards()[card].atlasRect / kTileSize;
    for (uint32_t y = rect.y; y < rect.y + rect.w; ++y) {
        for (uint32_t x = rect.x; x < rect.x + rect.z; ++x) {
            tiles.push_back(y * cards.atlas().tilesX() + x);
        }
    }
}

float halfAt(const std::vector<uint8_t>& bytes, size_t index) {
    return glm::unpackHalf1x16(uint16_t(bytes[2 * index] | (bytes[2 * index + 1] << 8)));
}

} // namespace

SurfaceCache::SurfaceCache(rhi::IDevice& device, const scene::Scene& scene, const gi::GpuScene& gpuScene,
                           const sdf::SceneSdf& sdf, const SurfaceCacheSettings& settings,
                           const SurfaceLightingSettings& lighting)
    : device_(device), cards_(scene, settings), atlas_(device, settings),
      capture_(device, scene, gpuScene, atlas_), tileOwner_(device, cards_.atlas()),
      allTiles_(device, settings.atlasSize, "surface cache card tiles"),
      radiosityTiles_(device, settings.atlasSize, "surface cache radiosity tiles"),
      directTiles_(device, settings.atlasSize, "surface cache direct-light tiles"),
      voxels_(device, gridOverCards(cards_, lighting.voxelResolution), sdf,
              1.0f / (settings.texelsPerUnit * settings.texelsPerUnit)),
      radiosity_(device, settings.atlasSize, sdf, gpuScene.sky, lighting.trace),
      schedule_(lighting.schedule, maxAlbedo(scene)), cardTiles_(tilesWithCards(cards_.atlas())),
      cardBvh_(buildCardBvh(cards_.cards())), lights_(scene.lights) {
    const size_t cardBytes = std::max<size_t>(cards_.cards().size(), 1) * sizeof(gpu::SurfaceCard);
    cardBuffer_ = device.createBuffer({.size = cardBytes,
                                       .structStride = sizeof(gpu::SurfaceCard),
                                       .usage = rhi::BufferUsage::Structured,
                                       .debugName = "surface cards"});
    // Moves keep the card count, so the tree keeps its node count: one buffer serves every rebuild.
    cardBvhBuffer_ = device.createBuffer({.size = cardBvh_.nodes.size() * sizeof(gpu::CardBvhNode),
                                          .structStride = sizeof(gpu::CardBvhNode),
                                          .usage = rhi::BufferUsage::Structured,
                                          .debugName = "surface card bvh"});
    schedule_.setTiles(cardTiles_);
}

void SurfaceCache::uploadCards(rhi::ICommandList& commands) {
    if (!cards_.cards().empty()) {
        commands.writeBuffer(*cardBuffer_, cards_.cards().data(),
                             cards_.cards().size() * sizeof(gpu::SurfaceCard));
    }
    commands.writeBuffer(*cardBvhBuffer_, cardBvh_.nodes.data(),
                         cardBvh_.nodes.size() * sizeof(gpu::CardBvhNode));
    tileOwner_.recordUpload(commands, cards_.atlas());
    allTiles_.recordUpload(commands, cardTiles_);
    cardsChanged_ = false;
}

bool SurfaceCache::recordDirectLight(gi::FrameContext& frame, const std::optional<gi::ShadowedLights>& lights,
                                     const std::vector<uint32_t>& capturedTiles) {
    const char* kPass = SurfaceCacheDirectLightPass::kPassName;
    if (!lights) {
        frame.skip(kPass, "no lights given");
        return false;
    }
    // Every card when the lights changed without setLights saying how (or on the first update);
    // otherwise the cards a changed light reaches, those a re-rendered shadow map covers, and
    // the cards just captured.
    const bool newVersion = directLightsVersion_ != lights->lightsVersion;
    const bool all = newVersion && announcedLightsVersion_ != lights->lightsVersion;
    std::vector<uint32_t> cards = newVersion ? relightCards_ : std::vector<uint32_t>{};
    glm::uvec4 reshadowed(0u);
    for (size_t light = 0; light < lights->shadowFrames.size() && light < LUMINA_CARD_LIGHT_MASK_BITS;
         ++light) {
        const uint64_t seen = light < directShadowFrames_.size() ? directShadowFrames_[light] : 0;
        if (lights->shadowFrames[light] != seen) {
            reshadowed[int(light / 32)] |= 1u << (light % 32);
        }
    }
    if (!all && reshadowed != glm::uvec4(0u)) {
        for (uint32_t card = 0; card < cards_.cards().size(); ++card) {
            if ((cards_.cards()[card].lightMask & reshadowed) != glm::uvec4(0u)) {
                cards.push_back(card);
            }
        }
    }
    std::vector<uint32_t> tiles;
    if (all) {
        tiles = cardTiles_;
    } else {
        std::sort(cards.begin(), cards.end());
        cards.erase(std::unique(cards.begin(), cards.end()), cards.end());
        for (uint32_t card : cards) {
            appendCardTiles(cards_, card, tiles);
        }
        tiles.insert(tiles.end(), capturedTiles.begin(), capturedTiles.end());
        std::sort(tiles.begin(), tiles.end());
        tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    }
    directLightsVersion_ = lights->lightsVersion;
    directShadowFrames_ = lights->shadowFrames;
    relightCards_.clear();
    if (tiles.empty() && !frame.mayReuse(kPass)) {
        tiles = cardTiles_; // forced: every card relit by the same lights, to the same values
    }
    if (tiles.empty()) {
        frame.skipReused(kPass, "no light, shadow or card changed");
        return false;
    }
    directTiles_.recordUpload(frame.commands(), tiles);
    const AtlasSurfaceBindings surfaces{atlas_, tileOwner_.texture(), cardBuffer_, capture_.depth()};
    directLight_.record(frame, surfaces, *lights, directTiles_);
    if (all) {
        schedule_.restart(); // the light the bounces carry changed everywhere
    } else if (!cards.empty()) {
        std::vector<scene::Bounds> regions;
        for (uint32_t card : cards) {
            regions.push_back(cardBounds(cards_.cards()[card]));
        }
        restartRadiosityNear(regions);
    }
    return true;
}

void SurfaceCache::restartRadiosityNear(std::span<const scene::Bounds> regions) {
    if (regions.empty()) {
        return;
    }
    const float reach = radiosity_.maxDistance();
    const auto grown = [reach](const scene::Bounds& box) {
        return scene::Bounds{box.min - glm::vec3(reach), box.max + glm::vec3(reach)};
    };
    scene::Bounds all, allCards;
    for (const scene::Bounds& region : regions) {
        all.extend(region);
    }
    for (const gpu::SurfaceCard& card : cards_.cards()) {
        allCards.extend(cardBounds(card));
    }
    // A region whose reach holds every card selects every card: skip the card-by-region test,
    // which is quadratic when a light change re-lights every card (the sun, in the city).
    const auto holdsEveryCard = [&](const scene::Bounds& region) {
        const scene::Bounds reached = grown(region);
        return glm::all(glm::lessThanEqual(reached.min, allCards.min)) &&
               glm::all(glm::lessThanEqual(allCards.max, reached.max));
    };
    if (std::any_of(regions.begin(), regions.end(), holdsEveryCard)) {
        schedule_.markDirty(cardTiles_);
        return;
    }
    std::vector<uint32_t> tiles;
    for (uint32_t card = 0; card < cards_.cards().size(); ++card) {
        const scene::Bounds reached = grown(cardBounds(cards_.cards()[card]));
        if (!reached.overlaps(all)) {
            continue; // quick reject against the union, then region by region
        }
        if (std::any_of(regions.begin(), regions.end(),
                        [&](const scene::Bounds& region) { return reached.overlaps(region); })) {
            appendCardTiles(cards_, card, tiles);
        }
    }
    schedule_.markDirty(tiles);
}

void SurfaceCache::updateLod(const glm::vec3& viewer) {
    const CardLodUpdate lod = cards_.updateLod(viewer);
    // With changes left and progress made (the budget ran out), plan again next frame even if the
    // viewer stands still; changes that found no room wait for the viewer to move, so a still
    // camera costs no planning.
    const bool again = lod.pending > 0 && lod.changed() > 0;
    lodViewer_ = again ? std::nullopt : std::optional<glm::vec3>(viewer);
    lodHistory_.last = lod;
    ++lodHistory_.updates;
    lodHistory_.evictions += lod.evicted;
    lodHistory_.maxEvictionsPerUpdate = std::max(lodHistory_.maxEvictionsPerUpdate, lod.evicted);
    if (lod.changed() > 0) {
        cardTiles_ = tilesWithCards(cards_.atlas());
        schedule_.setTiles(cardTiles_);
        // Reallocated tiles hold another card's radiosity history: bounces start over (blend 1).
        schedule_.restart();
        cardsChanged_ = true;
    }
}

void SurfaceCache::planLod(const std::optional<glm::vec3>& viewer) {
    if (viewer && lodViewer_ != viewer && !lodPlanned_) {
        updateLod(*viewer);
    }
    lodPlanned_ = true;
}

bool SurfaceCache::updateIsComputeOnly(const std::optional<gi::ShadowedLights>& lights) const {
    const bool lightsSeen = !lights || (directLightsVersion_ == lights->lightsVersion &&
                                        directShadowFrames_ == lights->shadowFrames);
    return initialised_ && updates_ > 0 && !cardsChanged_ && cards_.dirtyCardCount() == 0 &&
           relightCards_.empty() && lightsSeen;
}

void SurfaceCache::update(gi::FrameContext& frame, const std::optional<gi::ShadowedLights>& lights,
                          const std::optional<glm::vec3>& viewer) {
    planLod(viewer);
    lodPlanned_ = false;
    if (!initialised_) {
        atlas_.recordClear(frame.commands());
        voxels_.recordClear(frame.commands());
        radiosity_.recordClear(frame.commands());
        initialised_ = true;
    }
    if (cardsChanged_) {
        uploadCards(frame.commands());
    }

    // The first update captures everything (a load, not a frame in motion); later ones spread a
    // large change over frames, most useful cards first.
    std::vector<uint32_t> dirty =
        cards_.dirtyCards(updates_ == 0 ? UINT32_MAX : cards_.settings().capturesPerFrame);
    std::vector<uint32_t> dirtyTiles;
    if (dirty.empty() && !frame.mayReuse(kCapturePassName) && !cards_.cards().empty()) {
        // Forced: every card captured again from the same geometry, to the same texels (the
        // albedo's dither is fixed per texel). Nothing downstream is told: nothing changed, and
        // marking the tiles dirty would restart the radiosity every frame.
        std::vector<uint32_t> all(cards_.cards().size());
        std::iota(all.begin(), all.end(), 0u);
        capture_.record(frame, atlas_, cardBuffer_, cards_.cards(), all);
    } else if (dirty.empty()) {
        frame.skipReused(kCapturePassName, "no dirty cards");
    } else {
        capture_.record(frame, atlas_, cardBuffer_, cards_.cards(), dirty);
        for (uint32_t card : dirty) {
            cards_.markCaptured(card, uint32_t(frame.frameIndex()));
            appendCardTiles(cards_, card, dirtyTiles);
        }
        schedule_.markDirty(dirtyTiles);
    }
    lodHistory_.pendingCaptures = cards_.dirtyCardCount();

    const bool directChanged = recordDirectLight(frame, lights, dirtyTiles);

    // Combine and voxel lighting only when what they read changed: the capture, the direct
    // light, or the indirect light the last update's radiosity wrote.
    const bool combineForced = !frame.mayReuse(SurfaceCacheCombinePass::kPassName) ||
                               !frame.mayReuse(VoxelLightingPass::kInjectPassName) ||
                               !frame.mayReuse(VoxelLightingPass::kResolvePassName);
    if (!dirty.empty() || directChanged || indirectChanged_ || combineForced) {
        combine_.record(frame, atlas_, allTiles_, updates_);
        const AtlasSurfaceBindings surfaces{atlas_, tileOwner_.texture(), cardBuffer_, capture_.depth()};
        voxels_.record(frame, surfaces, allTiles_, updates_);
        indirectChanged_ = false;
    } else {
        frame.skipReused(SurfaceCacheCombinePass::kPassName, "nothing changed");
        frame.skipReused(VoxelLightingPass::kInjectPassName, "nothing changed");
        frame.skipReused(VoxelLightingPass::kResolvePassName, "nothing changed");
    }

    // Forced, converged radiosity goes on refining (the average of one more pass per tile).
    const std::vector<uint32_t> tiles = schedule_.next(!frame.mayReuse(RadiosityPass::kTracePassName));
    if (tiles.empty()) {
        const std::string reason =
            "converged after " + std::to_string(schedule_.requiredBounces()) + " bounces and " +
            std::to_string(schedule_.requiredUpdates() - schedule_.requiredBounces()) + " refinement passes";
        for (const char* pass : {RadiosityPass::kTracePassName, RadiosityPass::kFilterPassName,
                                 RadiosityPass::kIntegratePassName}) {
            frame.skipReused(pass, reason);
        }
    } else {
        radiosityTiles_.recordUpload(frame.commands(), tiles);
        const AtlasSurfaceBindings surfaces{atlas_, tileOwner_.texture(), cardBuffer_, capture_.depth()};
        radiosity_.record(frame, surfaces, voxels_, radiosityTiles_, schedule_.lastPass(),
                          schedule_.lastBlend());
        indirectChanged_ = true;
    }
    ++updates_;
}

void SurfaceCache::moveInstance(uint32_t instance, const glm::mat4& transform,
                                std::span<const scene::Light> lights) {
    std::vector<scene::Bounds> regions{instanceCardBounds(instance)};
    cards_.moveInstance(instance, transform, lights);
    regions.push_back(instanceCardBounds(instance));
    cardBvh_ = buildCardBvh(cards_.cards());
    cardTiles_ = tilesWithCards(cards_.atlas());
    schedule_.setTiles(cardTiles_);
    restartRadiosityNear(regions);
    cardsChanged_ = true;
}

void SurfaceCache::setLights(std::span<const scene::Light> lights, uint64_t lightsVersion) {
    const std::vector<uint32_t> touched = cards_.setLights(lights, scene::changedLights(lights_, lights));
    relightCards_.insert(relightCards_.end(), touched.begin(), touched.end());
    lights_.assign(lights.begin(), lights.end());
    announcedLightsVersion_ = lightsVersion;
    cardsChanged_ = true; // the masks
}

void SurfaceCache::instanceMaterialChanged(uint32_t instance) {
    cards_.markInstanceDirty(instance);
    restartRadiosityNear(std::vector<scene::Bounds>{instanceCardBounds(instance)});
}

scene::Bounds SurfaceCache::instanceCardBounds(uint32_t instance) const {
    scene::Bounds box;
    for (uint32_t card = cards_.firstCard(instance);
         card < cards_.firstCard(instance) + cards_.cardCount(instance); ++card) {
        box.extend(cardBounds(cards_.cards()[card]));
    }
    return box;
}

void SurfaceCache::lightsChanged() {
    schedule_.restart();
}

std::vector<glm::vec4> SurfaceCache::readLayer(AtlasLayer layer) const {
    const AtlasLayerView view = atlas_.layer(layer);
    const std::vector<uint8_t> bytes = rhi::readTexture(device_, *view.texture, {0, view.arrayLayer});
    const size_t texels = size_t(atlas_.size()) * atlas_.size();
    std::vector<glm::vec4> out(texels);
    for (size_t i = 0; i < texels; ++i) {
        for (int c = 0; c < 4; ++c) {
            out[i][c] = halfAt(bytes, 4 * i + size_t(c)); // every layer is RGBA16F
        }
    }
    return out;
}

std::vector<glm::vec4> SurfaceCache::readVoxelLighting() const {
    const std::vector<uint8_t> bytes = rhi::readTexture(device_, *voxels_.volume());
    std::vector<glm::vec4> out(bytes.size() / 8);
    for (size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < 4; ++c) {
            out[i][c] = halfAt(bytes, 4 * i + size_t(c));
        }
    }
    return out;
}

} // namespace lumina::surface_cache
