#include "gi/surface_cache/radiosity_schedule.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace lumina::surface_cache {

uint32_t bouncesToConverge(float maxAlbedo, const RadiosityScheduleSettings& settings) {
    if (!(maxAlbedo >= 0.0f && maxAlbedo <= 1.0f)) {
        throw std::invalid_argument("radiosity schedule: albedo " + std::to_string(maxAlbedo) +
                                    " is outside [0, 1]");
    }
    if (!(settings.tolerance > 0.0f && settings.tolerance < 1.0f) || settings.maxBounces == 0 ||
        settings.tilesPerUpdate == 0) {
        throw std::invalid_argument("radiosity schedule: tolerance " + std::to_string(settings.tolerance) +
                                    " (within (0, 1)), max bounces " + std::to_string(settings.maxBounces) +
                                    " and tiles per update " + std::to_string(settings.tilesPerUpdate) +
                                    " (both > 0)");
    }
    if (maxAlbedo <= settings.tolerance) {
        return 1; // a single bounce already leaves less than the tolerance
    }
    if (maxAlbedo >= 1.0f) {
        return settings.maxBounces; // a lossless surface never converges
    }
    const double bounces = std::ceil(std::log(double(settings.tolerance)) / std::log(double(maxAlbedo)));
    return uint32_t(std::clamp(bounces, 1.0, double(settings.maxBounces)));
}

RadiositySchedule::RadiositySchedule(const RadiosityScheduleSettings& settings, float maxAlbedo)
    : settings_(settings), required_(bouncesToConverge(maxAlbedo, settings)) {}

void RadiositySchedule::setTiles(std::span<const uint32_t> tiles) {
    std::unordered_map<uint32_t, TileState> old;
    for (const TileState& state : tiles_) {
        old.emplace(state.tile, state);
    }
    tiles_.clear();
    slot_.clear();
    for (uint32_t tile : tiles) {
        const auto it = old.find(tile);
        if (tile >= slot_.size()) {
            slot_.resize(size_t(tile) + 1, kNoSlot);
        }
        slot_[tile] = uint32_t(tiles_.size());
        tiles_.push_back(it != old.end() ? it->second : TileState{.tile = tile});
    }
}

void RadiositySchedule::markDirty(std::span<const uint32_t> tiles) {
    // Through the slot table: a city's first capture marks tens of thousands of tiles.
    for (uint32_t tile : tiles) {
        if (tile < slot_.size() && slot_[tile] != kNoSlot) {
            TileState& state = tiles_[slot_[tile]];
            state.dirty = true;
            state.updates = 0;
        }
    }
}

void RadiositySchedule::restart() {
    for (TileState& state : tiles_) {
        state.updates = 0;
    }
}

std::vector<uint32_t> RadiositySchedule::next(bool refineConverged) {
    if (tiles_.empty() || (converged() && !refineConverged)) {
        return {};
    }
    ++counter_;
    std::vector<uint32_t> order(tiles_.size());
    for (uint32_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    // Dirty first, then the fewest bounces, then the oldest; ties by tile index, so the
    // choice is deterministic.
    const auto before = [&](uint32_t a, uint32_t b) {
        const TileState& x = tiles_[a];
        const TileState& y = tiles_[b];
        if (x.dirty != y.dirty) {
            return x.dirty;
        }
        if (x.updates != y.updates) {
            return x.updates < y.updates;
        }
        if (x.lastUpdate != y.lastUpdate) {
            return x.lastUpdate < y.lastUpdate;
        }
        return x.tile < y.tile;
    };
    const size_t count = std::min<size_t>(settings_.tilesPerUpdate, order.size());
    std::partial_sort(order.begin(), order.begin() + ptrdiff_t(count), order.end(), before);
    // Picked fewest-updates first: the first is the least-updated tile.
    const uint32_t passes = tiles_[order[0]].updates;
    lastBlend_ = passes < required_ ? 1.0f : 1.0f / float(passes - required_ + 2);
    lastPass_ = passes;
    std::vector<uint32_t> picked;
    picked.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        TileState& state = tiles_[order[i]];
        state.dirty = false;
        ++state.updates;
        state.lastUpdate = counter_;
        picked.push_back(state.tile);
    }
    std::sort(picked.begin(), picked.end());
    return picked;
}

uint32_t RadiositySchedule::completedBounces() const {
    if (tiles_.empty()) {
        return 0;
    }
    uint32_t least = tiles_.front().updates;
    for (const TileState& state : tiles_) {
        least = std::min(least, state.updates);
    }
    return least;
}

} // namespace lumina::surface_cache
