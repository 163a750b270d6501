#include "gi/sh_grid/sh_grid_schedule.h"

#include <algorithm>
#include <numeric>

namespace lumina::gi {

ShGridSchedule::ShGridSchedule(const ShGridLayout& layout, uint32_t sweeps)
    : layout_(layout), sweeps_(sweeps), remaining_(layout.probes(), 0), dirty_(layout.probes(), 0) {
    invalidateAll();
}

void ShGridSchedule::owe(uint32_t probe, uint32_t bakes) {
    if (remaining_[probe] < bakes) {
        owed_ += bakes - remaining_[probe];
        remaining_[probe] = bakes;
        changedInSweep_ = true;
    }
}

void ShGridSchedule::invalidateAll() {
    for (uint32_t p = 0; p < remaining_.size(); ++p) {
        owe(p, sweeps_);
    }
}

void ShGridSchedule::changed(const scene::Bounds& region, float margin) {
    const glm::vec3 lo = region.min - glm::vec3(margin);
    const glm::vec3 hi = region.max + glm::vec3(margin);
    for (uint32_t p = 0; p < remaining_.size(); ++p) {
        const glm::vec3 at = layout_.position(p);
        const bool near = glm::all(glm::greaterThanEqual(at, lo)) && glm::all(glm::lessThanEqual(at, hi));
        if (near) {
            dirty_[p] = 1;
            owe(p, sweeps_);
        } else {
            owe(p, 1);
        }
    }
}

void ShGridSchedule::settle() {
    std::ranges::fill(remaining_, 0u);
    std::ranges::fill(dirty_, uint8_t(0));
    owed_ = 0;
}

std::vector<uint32_t> ShGridSchedule::next(uint32_t budget) {
    const uint32_t level = remaining_.empty() ? 0u : *std::ranges::max_element(remaining_);
    beganSweep_ = level > 0 && (level != sweepLevel_ || changedInSweep_);
    if (beganSweep_) {
        sweepLevel_ = level;
        changedInSweep_ = false;
    }
    std::vector<uint32_t> order;
    for (uint32_t p = 0; p < remaining_.size(); ++p) {
        if (level > 0 && remaining_[p] == level) {
            order.push_back(p);
        }
    }
    // Dirty probes first: a change's own neighbourhood is baked before the rest of its sweep.
    std::ranges::stable_sort(order, [&](uint32_t a, uint32_t b) { return dirty_[a] > dirty_[b]; });
    order.resize(std::min<size_t>(budget, order.size()));
    for (uint32_t p : order) {
        --remaining_[p];
        --owed_;
        dirty_[p] = 0;
    }
    return order;
}

uint32_t ShGridSchedule::dirtyProbes() const {
    return uint32_t(std::count(dirty_.begin(), dirty_.end(), uint8_t(1)));
}

} // namespace lumina::gi
