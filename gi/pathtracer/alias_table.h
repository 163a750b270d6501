#pragma once
// Vose's alias method (Vose, "A Linear Algorithm for Generating Random Numbers with a Given
// Distribution", IEEE TSE 17(9), 1991): O(1) sampling of a discrete distribution, used to
// pick an emissive triangle in proportion to its power.
#include "shaders/pathtracer/pathtracer_shared.h"

#include <span>
#include <vector>

namespace lumina::gi {

struct AliasTable {
    std::vector<gpu::PtAliasEntry> entries;
    std::vector<float> pdf; // probability of each outcome: weight / sum of weights
};

// Throws std::invalid_argument for an empty list, a negative or non-finite weight, or a zero sum.
AliasTable buildAliasTable(std::span<const double> weights);

// The outcome for uniform numbers uPick, uKeep in [0, 1), as the kernel draws it.
uint32_t sampleAliasTable(std::span<const gpu::PtAliasEntry> entries, float uPick, float uKeep);

} // namespace lumina::gi
