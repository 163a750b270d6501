// Vose's alias table: every outcome's total probability (kept where drawn, plus taken as the
// alias of others) equals its weight's share, and sampling through the kernel's rule agrees.
#include "gi/pathtracer/alias_table.h"

#include <gtest/gtest.h>
#include <random>
#include <stdexcept>
#include <vector>

namespace lumina::gi {
namespace {

// The probability of each outcome implied by the table.
std::vector<double> impliedProbabilities(const AliasTable& table) {
    const size_t n = table.entries.size();
    std::vector<double> p(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const double keep = std::min<double>(table.entries[i].probability, 1.0);
        p[i] += keep / double(n);
        p[table.entries[i].alias] += (1.0 - keep) / double(n);
    }
    return p;
}

TEST(AliasTable, ProbabilitiesMatchTheWeights) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> weight(0.0, 10.0);
    for (size_t n : {1u, 2u, 3u, 7u, 100u, 1000u}) {
        std::vector<double> weights(n);
        double sum = 0.0;
        for (double& w : weights) {
            w = (rng() % 5 == 0) ? 0.0 : weight(rng) * weight(rng); // zeros and a wide range
            sum += w;
        }
        if (sum == 0.0) {
            weights[0] = sum = 1.0;
        }
        const AliasTable table = buildAliasTable(weights);
        ASSERT_EQ(table.entries.size(), n);
        const std::vector<double> p = impliedProbabilities(table);
        for (size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(p[i], weights[i] / sum, 1e-6) << "n " << n << " outcome " << i;
            EXPECT_NEAR(table.pdf[i], weights[i] / sum, 1e-6) << "n " << n << " outcome " << i;
            EXPECT_LT(table.entries[i].alias, n);
        }
    }
}

TEST(AliasTable, SamplingFollowsTheWeights) {
    const std::vector<double> weights = {1.0, 0.0, 3.0, 6.0};
    const AliasTable table = buildAliasTable(weights);
    std::vector<uint32_t> counts(weights.size(), 0);
    constexpr uint32_t kGrid = 400; // a stratified grid of (uPick, uKeep)
    for (uint32_t i = 0; i < kGrid; ++i) {
        for (uint32_t j = 0; j < kGrid; ++j) {
            const float u1 = (float(i) + 0.5f) / kGrid, u2 = (float(j) + 0.5f) / kGrid;
            ++counts[sampleAliasTable(table.entries, u1, u2)];
        }
    }
    for (size_t k = 0; k < weights.size(); ++k) {
        EXPECT_NEAR(double(counts[k]) / (kGrid * kGrid), weights[k] / 10.0, 2e-3) << "outcome " << k;
    }
    EXPECT_EQ(counts[1], 0u) << "a zero weight is never drawn";
}

TEST(AliasTable, RejectsBadWeights) {
    EXPECT_THROW(buildAliasTable(std::vector<double>{}), std::invalid_argument);
    EXPECT_THROW(buildAliasTable(std::vector<double>{0.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(buildAliasTable(std::vector<double>{1.0, -1.0}), std::invalid_argument);
    EXPECT_THROW(buildAliasTable(std::vector<double>{1.0, NAN}), std::invalid_argument);
}

} // namespace
} // namespace lumina::gi
