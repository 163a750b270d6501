#pragma once
// Which atlas tiles radiosity updates each frame, and when it stops. A budget bounds the cost:
// at most tilesPerUpdate tiles per update, picked dirty first (cards just captured), then the
// least recently updated. Every tile updated once more is one more bounce of light; once every
// tile has had enough bounces for the light still missing (maxAlbedo^bounces) to fall below the
// tolerance, refinement passes follow: the probes average each new trace (rays rotated) with
// their history, 1 / (k + 1) for the k-th, which cuts the noise of 16 rays without biasing a
// converged answer. Then radiosity stops, until a light or object moves (restart).
#include <cstdint>
#include <span>
#include <vector>

namespace lumina::surface_cache {

struct RadiosityScheduleSettings {
    uint32_t tilesPerUpdate = 4096; // the budget: atlas tiles (16x16 texels) per update; 1 M texels
    float tolerance = 0.002f;       // stop when maxAlbedo^bounces falls below this...
    uint32_t maxBounces = 768;      // ...or after this many bounces, whichever first (rho = 0.99 needs
                                    // 619 at 0.002, 757 at the high preset's 0.0005)
    uint32_t refinementPasses = 16; // then this many averaged passes over every tile
};

// Bounces after which the light a further bounce adds, relative to the converged value, falls
// below settings.tolerance in a closed scene whose brightest albedo channel is maxAlbedo:
// ceil(log(tolerance) / log(maxAlbedo)), between 1 and maxBounces. Throws
// std::invalid_argument for an albedo outside [0, 1] or bad settings.
uint32_t bouncesToConverge(float maxAlbedo, const RadiosityScheduleSettings& settings);

class RadiositySchedule {
public:
    RadiositySchedule(const RadiosityScheduleSettings& settings, float maxAlbedo);

    // The tiles that hold cards (row-major atlas tile indices). A tile that stays keeps its
    // history; a new one starts dirty.
    void setTiles(std::span<const uint32_t> tiles);
    // These tiles' cards were captured anew: first in line at the next update.
    void markDirty(std::span<const uint32_t> tiles);
    // A light or object moved: bounces count from zero again.
    void restart();

    // This update's tiles (at most the budget), and counts them as updated; empty once converged,
    // unless `refineConverged`: then the refinement average goes on, one more pass per tile.
    std::vector<uint32_t> next(bool refineConverged = false);
    // The weight of this update's trace against the probes' history: 1 while bounces propagate,
    // 1 / (k + 1) in the k-th refinement pass (taken from the least-updated tile picked; with a
    // budget below the tile count the picked tiles differ by at most one pass).
    float lastBlend() const { return lastBlend_; }
    // Which update this one is for its tiles since the last restart (the same least-updated tile):
    // the radiosity trace's ray pattern, so that two runs which converge after a restart average
    // the same patterns, whatever ran before.
    uint32_t lastPass() const { return lastPass_; }

    // Bounces every tile has had since the last restart.
    uint32_t completedBounces() const;
    uint32_t requiredBounces() const { return required_; }
    // Bounces plus refinement passes: the updates of every tile until it stops.
    uint32_t requiredUpdates() const { return required_ + settings_.refinementPasses; }
    bool converged() const { return completedBounces() >= requiredUpdates(); }

private:
    struct TileState {
        uint32_t tile = 0;
        bool dirty = true;
        uint32_t updates = 0;    // since the last restart
        uint64_t lastUpdate = 0; // the update counter when it last ran; 0: never
    };
    RadiosityScheduleSettings settings_;
    uint32_t required_ = 1;
    uint64_t counter_ = 0;
    float lastBlend_ = 1.0f;
    uint32_t lastPass_ = 0;
    std::vector<TileState> tiles_;
    static constexpr uint32_t kNoSlot = 0xFFFFFFFFu;
    std::vector<uint32_t> slot_; // per atlas tile index: its entry in tiles_, or kNoSlot
};

} // namespace lumina::surface_cache
