// The adaptive allocation's slot sharing (shaders/screen_probes/adaptive_share_shared.h), through
// its C++ half: the 64-bit-free division against 64-bit arithmetic at the sizes a 4K or 8K image
// reaches, and the share keeping exactly `slots` candidates, spread evenly.
#include "shaders/screen_probes/adaptive_share_shared.h"

#include <algorithm>
#include <cstdint>
#include <gtest/gtest.h>
#include <random>

namespace lumina::test {
namespace {

TEST(AdaptiveShare, MulDivRemainderMatches64BitArithmetic) {
    std::mt19937 random(7);
    std::uniform_int_distribution<uint32_t> any;
    for (int i = 0; i < 100000; ++i) {
        const uint32_t d = 1u + any(random) % 0x7fffffffu;
        const uint32_t a = any(random) % d; // quotient below b, so it fits in 32 bits
        const uint32_t b = i % 4 == 0 ? any(random) : any(random) % 65536u;
        const uint64_t product = uint64_t(a) * b;
        const glm::uvec2 got = gpu::spMulDivRemainder(a, b, d);
        ASSERT_EQ(got.x, uint32_t(product / d)) << a << " x " << b << " / " << d;
        ASSERT_EQ(got.y, uint32_t(product % d)) << a << " x " << b << " / " << d;
    }
    // The extremes: the largest divisor, the largest factor, the largest rank below it.
    constexpr uint32_t d = 0x7fffffffu, a = d - 1u, b = 0xffffffffu;
    const uint64_t product = uint64_t(a) * b;
    const glm::uvec2 got = gpu::spMulDivRemainder(a, b, d);
    EXPECT_EQ(got.x, uint32_t(product / d));
    EXPECT_EQ(got.y, uint32_t(product % d));
}

// Every size from a few tiles to an 8K image's 2 M at half a cell of 8 px: exactly `slots` kept,
// slots 0, 1, 2, ... in rank order, and no run of skipped candidates longer than wanted / slots.
TEST(AdaptiveShare, KeepsExactlyTheSlotsSpreadEvenly) {
    const struct {
        uint32_t slots, wanted;
    } cases[] = {{8, 14},        {8, 8},          {16, 14},     {8160, 22000},
                 {14400, 25000}, {57600, 518400}, {1, 2073600}, {2073599, 2073600}};
    for (const auto& c : cases) {
        uint32_t kept = 0, skippedRun = 0, longestSkip = 0;
        for (uint32_t rank = 0; rank < c.wanted; ++rank) {
            const glm::uvec2 share = gpu::spAdaptiveShare(rank, c.slots, c.wanted);
            if (share.y == 0u) {
                longestSkip = std::max(longestSkip, ++skippedRun);
                continue;
            }
            ASSERT_EQ(share.x, kept) << "rank " << rank << " of " << c.wanted << " for " << c.slots;
            ++kept;
            skippedRun = 0;
        }
        EXPECT_EQ(kept, std::min(c.slots, c.wanted)) << c.wanted << " wanted, " << c.slots << " slots";
        const uint32_t evenGap = c.wanted > c.slots ? (c.wanted + c.slots - 1) / c.slots - 1 : 0u;
        EXPECT_LE(longestSkip, evenGap) << c.wanted << " wanted, " << c.slots << " slots";
        EXPECT_EQ(gpu::spAdaptiveShare(c.wanted - 1, c.slots, c.wanted).y, 1u)
            << "the last candidate keeps one";
    }
}

} // namespace
} // namespace lumina::test
