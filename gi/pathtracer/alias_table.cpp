#include "gi/pathtracer/alias_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::gi {

AliasTable buildAliasTable(std::span<const double> weights) {
    if (weights.empty()) {
        throw std::invalid_argument("alias table: no weights");
    }
    double sum = 0.0;
    for (size_t i = 0; i < weights.size(); ++i) {
        if (!std::isfinite(weights[i]) || weights[i] < 0.0) {
            throw std::invalid_argument("alias table: weight " + std::to_string(i) + " is " +
                                        std::to_string(weights[i]));
        }
        sum += weights[i];
    }
    if (!(sum > 0.0)) {
        throw std::invalid_argument("alias table: the weights sum to zero");
    }
    const size_t n = weights.size();
    AliasTable table;
    table.entries.resize(n);
    table.pdf.resize(n);
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        table.pdf[i] = float(weights[i] / sum);
        scaled[i] = weights[i] / sum * double(n);
        (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back();
        small.pop_back();
        const uint32_t l = large.back();
        table.entries[s] = {float(scaled[s]), l, 0, 0};
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What is left is 1 up to rounding: always kept.
    for (uint32_t i : large) {
        table.entries[i] = {1.0f, i, 0, 0};
    }
    for (uint32_t i : small) {
        table.entries[i] = {1.0f, i, 0, 0};
    }
    return table;
}

uint32_t sampleAliasTable(std::span<const gpu::PtAliasEntry> entries, float uPick, float uKeep) {
    const auto count = uint32_t(entries.size());
    const uint32_t index = std::min(uint32_t(uPick * float(count)), count - 1u);
    return uKeep >= entries[index].probability ? entries[index].alias : index;
}

} // namespace lumina::gi
