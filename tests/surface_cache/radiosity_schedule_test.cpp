// RadiositySchedule (gi/surface_cache/radiosity_schedule.h): the bounce count that converges,
// the budget, dirty-first-then-oldest order, convergence, restart.
#include "gi/surface_cache/radiosity_schedule.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <set>

namespace lumina::surface_cache {
namespace {

TEST(RadiositySchedule, BouncesToConvergeFollowTheGeometricSeries) {
    RadiosityScheduleSettings s;
    s.tolerance = 0.002f;
    s.maxBounces = 256;
    EXPECT_EQ(bouncesToConverge(0.5f, s), 9u);    // 0.5^9 = 0.00195
    EXPECT_EQ(bouncesToConverge(0.8f, s), 28u);   // 0.8^28 = 0.0019
    EXPECT_EQ(bouncesToConverge(0.95f, s), 122u); // 0.95^122 = 0.0019
    EXPECT_EQ(bouncesToConverge(0.99f, s), 256u); // 619 needed: capped
    EXPECT_EQ(bouncesToConverge(1.0f, s), 256u);
    EXPECT_EQ(bouncesToConverge(0.0f, s), 1u);
    EXPECT_EQ(bouncesToConverge(0.001f, s), 1u);
    // The default cap lets rho = 0.99 converge (docs/gi.md, energy).
    EXPECT_EQ(bouncesToConverge(0.99f, RadiosityScheduleSettings{}), 619u);
}

TEST(RadiositySchedule, RefusesBadInput) {
    const RadiosityScheduleSettings good;
    EXPECT_THROW(bouncesToConverge(1.5f, good), std::invalid_argument);
    EXPECT_THROW(bouncesToConverge(-0.1f, good), std::invalid_argument);
    EXPECT_THROW(bouncesToConverge(std::numeric_limits<float>::quiet_NaN(), good), std::invalid_argument);
    RadiosityScheduleSettings bad = good;
    bad.tolerance = 0.0f;
    EXPECT_THROW(bouncesToConverge(0.5f, bad), std::invalid_argument);
    bad = good;
    bad.tilesPerUpdate = 0;
    EXPECT_THROW(RadiositySchedule(bad, 0.5f), std::invalid_argument);
    try {
        bouncesToConverge(1.5f, good);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("1.5"), std::string::npos) << e.what();
    }
}

TEST(RadiositySchedule, BudgetDirtyFirstThenOldestUntilConverged) {
    RadiosityScheduleSettings s;
    s.tilesPerUpdate = 4;
    s.tolerance = 0.1f; // 0.5^4 = 0.0625: four bounces
    s.refinementPasses = 2;
    RadiositySchedule schedule(s, 0.5f);
    ASSERT_EQ(schedule.requiredBounces(), 4u);
    const std::vector<uint32_t> tiles = {3, 5, 8, 13, 21, 34, 55, 89, 144, 233};
    schedule.setTiles(tiles);
    EXPECT_EQ(schedule.completedBounces(), 0u);

    // Every tile starts dirty: the first three updates (12 picks) cover all ten, four at most
    // each, the two left over going to tiles that have had the fewest, then the oldest.
    std::multiset<uint32_t> seen;
    for (int update = 0; update < 3; ++update) {
        const std::vector<uint32_t> picked = schedule.next();
        EXPECT_LE(picked.size(), 4u);
        seen.insert(picked.begin(), picked.end());
    }
    EXPECT_EQ(seen.size(), 12u);
    EXPECT_EQ(std::set<uint32_t>(seen.begin(), seen.end()), std::set<uint32_t>(tiles.begin(), tiles.end()));
    EXPECT_EQ(schedule.completedBounces(), 1u);

    // A freshly captured tile jumps the queue.
    const std::vector<uint32_t> dirty = {144};
    schedule.markDirty(dirty);
    EXPECT_EQ(schedule.completedBounces(), 0u); // its bounces start over
    std::vector<uint32_t> picked = schedule.next();
    EXPECT_NE(std::find(picked.begin(), picked.end(), 144u), picked.end());

    // Oldest next: the tiles not picked the longest come first.
    const std::vector<uint32_t> before = picked;
    picked = schedule.next();
    for (uint32_t tile : picked) {
        EXPECT_EQ(std::find(before.begin(), before.end(), tile), before.end())
            << tile << " picked twice in a row";
    }

    uint32_t updates = 0;
    std::vector<float> blends;
    while (!schedule.converged() && updates < 100) {
        EXPECT_FALSE(schedule.next().empty());
        blends.push_back(schedule.lastBlend());
        ++updates;
    }
    ASSERT_TRUE(schedule.converged());
    EXPECT_EQ(schedule.requiredUpdates(), 6u);
    EXPECT_EQ(schedule.completedBounces(), 6u); // 4 bounces, 2 refinement passes
    // Bounces replace the probes; the refinement passes average 1/2, then 1/3.
    EXPECT_EQ(blends.front(), 1.0f);
    EXPECT_FLOAT_EQ(blends.back(), 1.0f / 3.0f);
    EXPECT_NE(std::find(blends.begin(), blends.end(), 0.5f), blends.end());
    EXPECT_TRUE(schedule.next().empty()) << "converged: nothing to do";

    // Forced on (lumina bench --verify-skips), converged radiosity goes on refining: the least
    // updated tiles first, each pass averaged in at a smaller weight than the last.
    const float lastBlend = schedule.lastBlend();
    EXPECT_EQ(schedule.next(/*refineConverged=*/true).size(), 4u);
    EXPECT_LE(schedule.lastBlend(), lastBlend);
    EXPECT_GT(schedule.lastBlend(), 0.0f);
    EXPECT_TRUE(schedule.converged());
    EXPECT_TRUE(schedule.next().empty()) << "not forced: still nothing to do";

    // A light moved: everything runs again, and the ray patterns start over with the passes
    // (lastPass: the least-updated picked tile's updates before this one), so that a run which
    // converges again averages the patterns a fresh run would.
    EXPECT_GT(schedule.lastPass(), 0u);
    schedule.restart();
    EXPECT_FALSE(schedule.converged());
    EXPECT_EQ(schedule.next().size(), 4u);
    EXPECT_EQ(schedule.lastPass(), 0u);
    // Ten tiles at four a time: the third update still picks two that had none.
    for (int update = 0; update < 2; ++update) {
        schedule.next();
        EXPECT_EQ(schedule.lastPass(), 0u);
    }
    schedule.next();
    EXPECT_EQ(schedule.lastPass(), 1u);
}

TEST(RadiositySchedule, NewTilesStartDirtyAndKeptTilesKeepTheirBounces) {
    RadiosityScheduleSettings s;
    s.tilesPerUpdate = 2;
    s.tolerance = 0.1f;
    s.refinementPasses = 0;
    RadiositySchedule schedule(s, 0.5f);
    const std::vector<uint32_t> first = {1, 2};
    schedule.setTiles(first);
    schedule.next();
    schedule.next();
    EXPECT_EQ(schedule.completedBounces(), 2u);
    const std::vector<uint32_t> second = {1, 2, 7};
    schedule.setTiles(second);
    EXPECT_EQ(schedule.completedBounces(), 0u); // tile 7 has none
    const std::vector<uint32_t> picked = schedule.next();
    EXPECT_NE(std::find(picked.begin(), picked.end(), 7u), picked.end());
}

} // namespace
} // namespace lumina::surface_cache
