#pragma once
// Which probes the SH grid bakes this frame (docs/sh_grid.md, "Updates"): a budget of probes per
// frame; after a change, the probes near it first, then one more bake of every other probe
// (their cube maps may see the change too); nothing at all when nothing changed.
//
//   ShGridSchedule schedule(layout, settings.sweeps);   // every probe owes `sweeps` bakes
//   schedule.changed(movedBox, spacing);                // near ones dirty, the rest owe one more
//   for (uint32_t probe : schedule.next(budget)) bake(probe);
#include "gi/scene/scene.h"
#include "gi/sh_grid/sh_grid_settings.h"

#include <cstdint>
#include <vector>

namespace lumina::gi {

class ShGridSchedule {
public:
    ShGridSchedule(const ShGridLayout& layout, uint32_t sweeps);

    // Every probe owes `sweeps` bakes (the start, or a change that reaches everything).
    void invalidateAll();
    // Something changed in `region`: probes within `margin` of it are dirty (baked before any
    // other) and owe `sweeps` bakes; every other probe owes at least one.
    void changed(const scene::Bounds& region, float margin);
    // Nothing owed (a grid loaded from a file).
    void settle();

    // Up to `budget` probes to bake now, all of the current sweep (those owing the most bakes),
    // dirty ones first, by index; counts their bakes as done. A batch never spans two sweeps: a
    // sweep's bounces read the grid as it stood when the sweep began (Jacobi, not Gauss-Seidel),
    // so each sweep adds exactly one bounce, and baking a probe again once nothing is owed gives
    // exactly the value it has (the skip that `lumina bench --verify-skips` checks).
    std::vector<uint32_t> next(uint32_t budget);
    // Whether the batch the last next() returned began a sweep (or followed a change): the grid is
    // copied to the bounce source before it bakes.
    bool batchBeganSweep() const { return beganSweep_; }

    bool idle() const { return owed_ == 0; }
    uint64_t owedBakes() const { return owed_; }
    uint32_t dirtyProbes() const;
    uint32_t probeCount() const { return uint32_t(remaining_.size()); }

private:
    void owe(uint32_t probe, uint32_t bakes);

    ShGridLayout layout_;
    uint32_t sweeps_;
    std::vector<uint32_t> remaining_; // per probe: bakes still owed
    std::vector<uint8_t> dirty_;      // per probe: near a change since its last bake
    uint64_t owed_ = 0;
    uint32_t sweepLevel_ = 0;    // the bakes owed by the probes of the sweep under way; 0: none
    bool changedInSweep_ = true; // owe() raised a probe since the sweep began
    bool beganSweep_ = false;
};

} // namespace lumina::gi
