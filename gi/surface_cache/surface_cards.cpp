#include "gi/surface_cache/surface_cards.h"

#include "gi/surface_cache/light_mask.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace lumina::surface_cache {
namespace {

uint32_t flagsOf(const gpu::SurfaceCard& card) {
    return gpu::asuint(card.boundsMinAndFlags.w);
}

// The buddy level of a rectangle: larger blocks placed first pack without gaps.
uint32_t blockLevel(glm::uvec2 tiles) {
    return uint32_t(std::bit_width(std::max(tiles.x, tiles.y) - 1u));
}

} // namespace

const char* axisName(uint32_t axis) {
    static const char* const names[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return axis < 6 ? names[axis] : "?";
}

SurfaceCards::SurfaceCards(const scene::Scene& scene, const SurfaceCacheSettings& settings,
                           std::optional<glm::vec3> viewer)
    : settings_((validate(settings), settings)),
      atlas_(settings.atlasSize / kTileSize, settings.atlasSize / kTileSize) {
    if (scene.lights.size() > LUMINA_CARD_LIGHT_MASK_BITS) {
        throw std::invalid_argument("SurfaceCards: scene '" + scene.name + "' has " +
                                    std::to_string(scene.lights.size()) + " lights; card light masks hold " +
                                    std::to_string(LUMINA_CARD_LIGHT_MASK_BITS));
    }
    for (const scene::Mesh& mesh : scene.meshes) {
        meshCards_.push_back(buildMeshCards(mesh, scene.materials, settings_));
        meshNames_.push_back(mesh.name);
    }
    instanceFirst_.push_back(0);
    for (const scene::Instance& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) {
            throw std::invalid_argument("SurfaceCards: instance '" + instance.name + "' names mesh " +
                                        std::to_string(instance.mesh) + " of " +
                                        std::to_string(scene.meshes.size()));
        }
        instanceFirst_.push_back(instanceFirst_.back() + uint32_t(meshCards_[instance.mesh].size()));
        instanceNames_.push_back(instance.name);
    }
    const size_t count = instanceFirst_.back();
    cards_.resize(count);
    cardTiles_.resize(count);
    fullTiles_.resize(count);
    surfaceBounds_.resize(count);
    levels_.assign(count, kCardEvicted);
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        for (uint32_t c = 0; c < meshCards_[instance.mesh].size(); ++c) {
            const uint32_t card = instanceFirst_[i] + c;
            cards_[card].info = glm::uvec4(instance.mesh, c, meshCards_[instance.mesh][c].axis, 0u);
            cards_[card].boundsMaxAndInstance.w = gpu::asfloat(i);
            placeGeometry(card, meshCards_[instance.mesh][c], instance.transform, scene.lights,
                          LUMINA_CARD_DIRTY | LUMINA_CARD_STATIC);
        }
    }

    priorities_ = prioritiesFrom(viewer.value_or(scene.camera.position));
    const CardLodPlan planned = plan(priorities_);
    // Largest blocks first (a buddy allocator packs descending sizes without gaps), then the most
    // useful, so that what the allocator cannot place after all is the least useful.
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    const auto plannedTiles = [&](uint32_t card) {
        return tilesAtLevel(fullTiles_[card].x, fullTiles_[card].y, planned.levels[card]);
    };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const bool evictedA = planned.levels[a] == kCardEvicted, evictedB = planned.levels[b] == kCardEvicted;
        if (evictedA != evictedB) {
            return evictedB;
        }
        if (!evictedA && blockLevel(plannedTiles(a)) != blockLevel(plannedTiles(b))) {
            return blockLevel(plannedTiles(a)) > blockLevel(plannedTiles(b));
        }
        return priorities_[a] > priorities_[b];
    });
    for (uint32_t card : order) {
        if (planned.levels[card] == kCardEvicted) {
            evict(card);
        } else {
            assign(card, planned.levels[card], false);
        }
    }
}

uint32_t SurfaceCards::instanceOf(uint32_t card) const {
    if (card >= cards_.size()) {
        throw std::out_of_range("SurfaceCards: card " + std::to_string(card) + " of " +
                                std::to_string(cards_.size()));
    }
    return uint32_t(std::upper_bound(instanceFirst_.begin(), instanceFirst_.end(), card) -
                    instanceFirst_.begin()) -
           1u;
}

std::string SurfaceCards::describe(uint32_t card) const {
    const uint32_t instance = instanceOf(card);
    const gpu::SurfaceCard& c = cards_[card];
    return "card " + std::to_string(card) + " (instance '" + instanceNames_[instance] + "', mesh '" +
           meshNames_[c.info.x] + "', " + axisName(c.info.z) + ")";
}

void SurfaceCards::placeGeometry(uint32_t card, const MeshCard& meshCard, const glm::mat4& transform,
                                 std::span<const scene::Light> lights, uint32_t flags) {
    PlacedCard placed;
    try {
        placed = placeCard(meshCard, transform, settings_);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(describe(card) + ": " + e.what());
    }
    const glm::uvec4 info = cards_[card].info;
    const float instanceBits = cards_[card].boundsMaxAndInstance.w;
    const glm::uvec4 rect = cards_[card].atlasRect;
    const uint32_t visible = flagsOf(cards_[card]) & LUMINA_CARD_VISIBLE;
    gpu::SurfaceCard& c = cards_[card];
    c = placed.card;
    c.info = glm::uvec4(info.x, info.y, meshCard.axis, info.w);
    c.boundsMaxAndInstance.w = instanceBits;
    c.boundsMinAndFlags.w = gpu::asfloat(flags | visible | (meshCard.twoSided ? LUMINA_CARD_TWO_SIDED : 0u));
    c.atlasRect = rect;
    c.lightMask = lightMask(placed.unpaddedBounds, lights);
    surfaceBounds_[card] = placed.unpaddedBounds;
    fullTiles_[card] = glm::uvec2(placed.tilesX, placed.tilesY);
}

void SurfaceCards::setFlag(uint32_t card, uint32_t flag, bool on) {
    gpu::SurfaceCard& c = cards_[card];
    c.boundsMinAndFlags.w = gpu::asfloat(on ? (flagsOf(c) | flag) : (flagsOf(c) & ~flag));
}

void SurfaceCards::setAtlasRect(uint32_t card, const TileRect& tiles) {
    cardTiles_[card] = tiles;
    cards_[card].atlasRect = glm::uvec4(tiles.x * kTileSize, tiles.y * kTileSize, tiles.width * kTileSize,
                                        tiles.height * kTileSize);
    setFlag(card, LUMINA_CARD_VISIBLE, tiles.area() != 0);
}

void SurfaceCards::evict(uint32_t card) {
    if (cardTiles_[card].area() != 0) {
        atlas_.release(cardTiles_[card]);
    }
    setAtlasRect(card, {});
    levels_[card] = kCardEvicted;
}

uint8_t SurfaceCards::assign(uint32_t card, uint32_t level, bool keepOnFailure) {
    const TileRect old = cardTiles_[card];
    const uint8_t oldLevel = levels_[card];
    if (!keepOnFailure && old.area() != 0) {
        atlas_.release(old);
        setAtlasRect(card, {});
    }
    bool defragmented = false;
    const uint32_t coarsest = keepOnFailure ? level : settings_.maxLodLevel;
    for (uint32_t l = level; l <= coarsest; ++l) {
        const glm::uvec2 tiles = tilesAtLevel(fullTiles_[card].x, fullTiles_[card].y, l);
        std::optional<TileRect> rect = atlas_.tryAllocate(tiles.x, tiles.y, card);
        if (!rect && !defragmented && atlas_.freeTiles() >= tiles.x * tiles.y) {
            // Enough space, but in pieces: repack the live cards (they must be captured again).
            defragmented = true;
            for (const TileRelocation& moved : atlas_.defragment()) {
                setAtlasRect(moved.owner, moved.to);
                setFlag(moved.owner, LUMINA_CARD_DIRTY, true);
            }
            rect = atlas_.tryAllocate(tiles.x, tiles.y, card);
        }
        if (rect) {
            if (keepOnFailure && cardTiles_[card].area() != 0) {
                atlas_.release(cardTiles_[card]);
            }
            setAtlasRect(card, *rect);
            setFlag(card, LUMINA_CARD_DIRTY, true);
            levels_[card] = uint8_t(l);
            return levels_[card];
        }
    }
    if (keepOnFailure) {
        return oldLevel;
    }
    evict(card);
    return kCardEvicted;
}

std::vector<float> SurfaceCards::prioritiesFrom(const glm::vec3& viewer) const {
    std::vector<float> priorities(cards_.size());
    for (size_t i = 0; i < cards_.size(); ++i) {
        priorities[i] = cardPriority(cardBounds(cards_[i]), viewer);
    }
    return priorities;
}

CardLodPlan SurfaceCards::plan(const std::vector<float>& priorities) const {
    std::vector<CardLodRequest> requests(cards_.size());
    for (size_t i = 0; i < cards_.size(); ++i) {
        requests[i] = {fullTiles_[i].x, fullTiles_[i].y, cardBounds(cards_[i])};
    }
    const uint64_t capacity = uint64_t(atlas_.tilesX()) * atlas_.tilesY();
    const auto budget = uint64_t(double(capacity) * double(settings_.atlasFill));
    return planCardLod(requests, priorities, budget, settings_.maxLodLevel);
}

CardLodUpdate SurfaceCards::updateLod(const glm::vec3& viewer) {
    priorities_ = prioritiesFrom(viewer);
    const CardLodPlan planned = plan(priorities_);
    // A card keeps its level while the level its size would get, nudged by the hysteresis
    // factor either way, still brackets it: no back and forth at a bound.
    struct Change {
        uint32_t card;
        uint8_t level;
    };
    std::vector<Change> freeing, taking;
    for (uint32_t card = 0; card < cards_.size(); ++card) {
        const uint8_t current = levels_[card];
        const uint8_t wanted = planned.levels[card];
        if (wanted == current) {
            continue;
        }
        if (wanted != kCardEvicted && current != kCardEvicted) {
            const float p = priorities_[card];
            const uint32_t finest =
                lodLevel(p * settings_.lodHysteresis, planned.reference, settings_.maxLodLevel);
            const uint32_t coarsest =
                lodLevel(p / settings_.lodHysteresis, planned.reference, settings_.maxLodLevel);
            if (current >= finest && current <= coarsest) {
                continue;
            }
        }
        const bool frees = wanted == kCardEvicted || (current != kCardEvicted && wanted > current);
        (frees ? freeing : taking).push_back({card, wanted});
    }
    // Room first, least useful first; then the most useful of those that take room.
    std::stable_sort(freeing.begin(), freeing.end(), [&](const Change& a, const Change& b) {
        return priorities_[a.card] < priorities_[b.card];
    });
    std::stable_sort(taking.begin(), taking.end(), [&](const Change& a, const Change& b) {
        return priorities_[a.card] > priorities_[b.card];
    });

    CardLodUpdate update;
    uint32_t budget = settings_.lodChangesPerFrame;
    for (const std::vector<Change>* list : {&freeing, &taking}) {
        for (const Change& change : *list) {
            if (budget == 0) {
                ++update.pending;
                continue;
            }
            const uint8_t before = levels_[change.card];
            if (change.level == kCardEvicted) {
                evict(change.card);
                setFlag(change.card, LUMINA_CARD_DIRTY, false);
                ++update.evicted;
                --budget;
                continue;
            }
            // A finer level replaces the old rectangle only once the new one is found.
            const bool finer = before != kCardEvicted && change.level < before;
            const uint8_t got = assign(change.card, change.level, finer);
            if (got == before) {
                ++update.pending; // no room yet: try again on a later frame
                continue;
            }
            --budget;
            if (before == kCardEvicted) {
                update.restored += got != kCardEvicted ? 1u : 0u;
            } else if (got == kCardEvicted) {
                ++update.evicted;
            } else if (got < before) {
                ++update.refined;
            } else {
                ++update.coarsened;
            }
        }
    }
    return update;
}

std::string toString(const AtlasOccupancy& o) {
    char percent[32];
    std::snprintf(percent, sizeof(percent), "%.1f%%",
                  o.totalTiles ? 100.0 * o.usedTiles / o.totalTiles : 0.0);
    std::string text = std::to_string(o.usedTiles) + " of " + std::to_string(o.totalTiles) + " tiles (" +
                       percent + "); " + std::to_string(o.cards) + " cards:";
    bool first = true;
    for (size_t level = 0; level < o.cardsAtLevel.size(); ++level) {
        if (o.cardsAtLevel[level] == 0) {
            continue;
        }
        text += std::string(first ? " " : ", ") + std::to_string(o.cardsAtLevel[level]) +
                (level == 0 ? " at full density" : " at 1/" + std::to_string(1u << level));
        first = false;
    }
    return text + "; " + std::to_string(o.evicted) + " evicted (lit by the voxel lighting)";
}

AtlasOccupancy SurfaceCards::occupancy() const {
    AtlasOccupancy o;
    o.usedTiles = atlas_.usedTiles();
    o.totalTiles = atlas_.tilesX() * atlas_.tilesY();
    o.cardsAtLevel.assign(settings_.maxLodLevel + 1, 0u);
    o.cards = uint32_t(cards_.size());
    for (uint8_t level : levels_) {
        if (level == kCardEvicted) {
            ++o.evicted;
        } else {
            ++o.cardsAtLevel.at(level);
        }
    }
    return o;
}

std::vector<uint32_t> SurfaceCards::setLights(std::span<const scene::Light> lights,
                                              std::span<const uint32_t> changedLights) {
    glm::uvec4 changed(0u);
    for (uint32_t light : changedLights) {
        if (light < LUMINA_CARD_LIGHT_MASK_BITS) {
            changed[int(light / 32)] |= 1u << (light % 32);
        }
    }
    std::vector<glm::uvec4> masks(cards_.size());
    for (size_t card = 0; card < cards_.size(); ++card) {
        masks[card] = lightMask(surfaceBounds_[card], lights); // throws before anything changed
    }
    std::vector<uint32_t> touched;
    for (uint32_t card = 0; card < cards_.size(); ++card) {
        const glm::uvec4 reached = (cards_[card].lightMask | masks[card]) & changed;
        if (reached != glm::uvec4(0u)) {
            touched.push_back(card);
        }
        cards_[card].lightMask = masks[card];
    }
    return touched;
}

void SurfaceCards::markInstanceDirty(uint32_t instance) {
    if (instance + 1 >= instanceFirst_.size()) {
        throw std::out_of_range("SurfaceCards::markInstanceDirty: instance " + std::to_string(instance) +
                                " of " + std::to_string(instanceFirst_.size() - 1));
    }
    for (uint32_t card = instanceFirst_[instance]; card < instanceFirst_[instance + 1]; ++card) {
        setFlag(card, LUMINA_CARD_DIRTY, true);
    }
}

void SurfaceCards::moveInstance(uint32_t instance, const glm::mat4& transform,
                                std::span<const scene::Light> lights) {
    if (instance + 1 >= instanceFirst_.size()) {
        throw std::out_of_range("SurfaceCards::moveInstance: instance " + std::to_string(instance) + " of " +
                                std::to_string(instanceFirst_.size() - 1));
    }
    // Placed on a copy and committed at the end: a singular transform throws and leaves every
    // card and the atlas as they were.
    SurfaceCards next = *this;
    const uint32_t first = instanceFirst_[instance], end = instanceFirst_[instance + 1];
    for (uint32_t card = first; card < end; ++card) {
        const gpu::SurfaceCard& c = next.cards_[card];
        next.placeGeometry(card, meshCards_[c.info.x][c.info.y], transform, lights,
                           LUMINA_CARD_DIRTY | LUMINA_CARD_DYNAMIC);
        const uint8_t level = next.levels_[card];
        if (level == kCardEvicted) {
            continue;
        }
        const glm::uvec2 tiles = tilesAtLevel(next.fullTiles_[card].x, next.fullTiles_[card].y, level);
        const TileRect& old = next.cardTiles_[card];
        if (old.width != tiles.x || old.height != tiles.y) {
            next.assign(card, level, false);
        }
    }
    // The capture clears the texels another instance hides (card_capture_pass.h): the cards
    // the instance overlapped before or after the move are captured again.
    for (uint32_t card = 0; card < next.cards_.size(); ++card) {
        if (card >= first && card < end) {
            continue;
        }
        const scene::Bounds bounds = cardBounds(next.cards_[card]);
        for (uint32_t moved = first; moved < end; ++moved) {
            if (bounds.overlaps(cardBounds(cards_[moved])) ||
                bounds.overlaps(cardBounds(next.cards_[moved]))) {
                next.setFlag(card, LUMINA_CARD_DIRTY, true);
                break;
            }
        }
    }
    *this = std::move(next);
}

void SurfaceCards::markCaptured(uint32_t card, uint32_t frame) {
    if (card >= cards_.size()) {
        throw std::out_of_range("SurfaceCards::markCaptured: card " + std::to_string(card) + " of " +
                                std::to_string(cards_.size()));
    }
    setFlag(card, LUMINA_CARD_DIRTY, false);
    cards_[card].info.w = frame;
}

uint32_t SurfaceCards::dirtyCardCount() const {
    uint32_t count = 0;
    for (uint32_t i = 0; i < cards_.size(); ++i) {
        count += (flagsOf(cards_[i]) & LUMINA_CARD_DIRTY) && cardTiles_[i].area() != 0 ? 1u : 0u;
    }
    return count;
}

std::vector<uint32_t> SurfaceCards::dirtyCards(uint32_t limit) const {
    std::vector<uint32_t> dirty;
    for (uint32_t i = 0; i < cards_.size(); ++i) {
        if ((flagsOf(cards_[i]) & LUMINA_CARD_DIRTY) && cardTiles_[i].area() != 0) {
            dirty.push_back(i);
        }
    }
    if (dirty.size() > limit) {
        // The most useful first; the rest wait for the next frames.
        std::stable_sort(dirty.begin(), dirty.end(),
                         [&](uint32_t a, uint32_t b) { return priorities_[a] > priorities_[b]; });
        dirty.resize(limit);
        std::sort(dirty.begin(), dirty.end());
    }
    return dirty;
}

} // namespace lumina::surface_cache
