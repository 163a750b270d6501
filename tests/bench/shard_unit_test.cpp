// --shard i/n parsing, the row bands of reference shards and the units of bench shards.
#include "gi/bench/bench_matrix.h"
#include "gi/bench/shard.h"

#include <gtest/gtest.h>
#include <set>
#include <stdexcept>

namespace lumina::gi {
namespace {

TEST(Shard, ParsesIOfN) {
    const Shard shard = parseShard("2/5");
    EXPECT_EQ(shard.index, 2u);
    EXPECT_EQ(shard.count, 5u);
    EXPECT_EQ(shard.text(), "2/5");
    for (const char* bad : {"", "3", "1/", "/4", "4/4", "5/4", "0/0", "-1/4", "1/4x", "a/b", "1 /4"}) {
        EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
    }
}

TEST(Shard, RowBandsCoverTheImageOnceInOrder) {
    for (uint32_t height : {4u, 18u, 1080u}) {
        for (uint32_t count : {1u, 3u, 4u}) {
            uint32_t next = 0;
            for (uint32_t i = 0; i < count; ++i) {
                const RowBand band = shardRows(height, {i, count});
                EXPECT_EQ(band.first, next);
                EXPECT_GE(band.count, height / count);
                EXPECT_LE(band.count, height / count + 1);
                next += band.count;
            }
            EXPECT_EQ(next, height);
        }
    }
    EXPECT_THROW(shardRows(3, {0, 4}), std::invalid_argument);
}

TEST(BenchMatrix, RowsInOneRunsOrderAndUnitsCoverThemOnce) {
    const BenchMatrix matrix{
        .scenes = 2, .techniques = {"pathtracer", "lumen", "direct"}, .presets = 3, .budgets = 2};
    EXPECT_EQ(matrix.timeBase(), "lumen");
    EXPECT_EQ(matrix.rowCount(), 2u * (2 * 3 + 2));
    EXPECT_EQ(matrix.realTimeRow(0, "lumen", 0), 0u);
    EXPECT_EQ(matrix.realTimeRow(0, "direct", 2), 5u);
    EXPECT_EQ(matrix.pathTracerRow(0, 1), 7u);
    EXPECT_EQ(matrix.realTimeRow(1, "lumen", 1), 9u);

    const std::vector<BenchUnit> units = benchUnits(matrix);
    ASSERT_EQ(units.size(), 4u);
    std::set<size_t> rows;
    for (const BenchUnit& unit : units) {
        for (size_t p = 0; p < matrix.presets; ++p) {
            EXPECT_TRUE(rows.insert(matrix.realTimeRow(unit.scene, unit.technique, p)).second);
        }
        // The path tracer goes with the technique whose frame its budgets multiply.
        EXPECT_EQ(unit.withPathTracer, unit.technique == "lumen");
        for (size_t b = 0; unit.withPathTracer && b < matrix.budgets; ++b) {
            EXPECT_TRUE(rows.insert(matrix.pathTracerRow(unit.scene, b)).second);
        }
    }
    EXPECT_EQ(rows.size(), matrix.rowCount());

    const BenchMatrix ptOnly{
        .scenes = 1, .techniques = {"sh-grid", "pathtracer"}, .presets = 1, .budgets = 3};
    const std::vector<BenchUnit> alone = benchUnits(ptOnly);
    ASSERT_EQ(alone.size(), 2u);
    EXPECT_EQ(alone[1].technique, "pathtracer");
    EXPECT_TRUE(alone[1].withPathTracer);
}

} // namespace
} // namespace lumina::gi
