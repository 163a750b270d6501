#pragma once
// Which atlas tiles radiosity updates each frame, and when it stops. A budget bounds the cost:
// at most tilesPerUpdate tiles per update, picked dirty first (cards just captured), then the
// least recently updated. Every tile updated once more is one more bounce of light; once every
// tile has had enough bounces for the light still missing (maxAlbedo^bounces) to fall below the
// tolerance, radiosity is converged and stops, until a light or object moves (restart).
#include <cstdint>
#include <span>
#include <vector>

namespace lumina::surface_cache {

struct RadiosityScheduleSettings {
    uint32_t tilesPerUpdate = 256; // the budget (64x64-texel tiles per update)
    float tolerance = 0.002f;      // stop when maxAlbedo^bounces falls below this...
    uint32_t maxBounces = 256;     // ...or after this many bounces, whichever comes first
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

    // This update's tiles (at most the budget), and counts them as updated; empty once converged.
    std::vector<uint32_t> next();

    // Bounces every tile has had since the last restart.
    uint32_t completedBounces() const;
    uint32_t requiredBounces() const { return required_; }
    bool converged() const { return completedBounces() >= required_; }

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
    std::vector<TileState> tiles_;
};

} // namespace lumina::surface_cache
