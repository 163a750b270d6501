#include "gi/core/timing_table.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace lumina::gi {
namespace {

rhi::TimerResult timer(const char* name, double ms, uint64_t begin, uint64_t end) {
    return {name, ms, begin, end};
}

TEST(Median, OddEvenAndEmpty) {
    EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
    EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_DOUBLE_EQ(median({}), 0.0);
}

TEST(TimingTable, SkipsWarmupAndAggregatesPerPass) {
    TimingTable table(/*warmupFrames=*/1);
    table.addFrame({timer("gbuffer", 100.0, 0, 10)}); // warm-up, ignored
    table.addFrame({timer("gbuffer", 1.0, 0, 10), timer("light", 2.0, 10, 20)});
    table.addFrame({timer("gbuffer", 3.0, 0, 10), timer("light", 4.0, 10, 20)});
    table.addFrame({timer("gbuffer", 2.0, 0, 10), timer("light", 6.0, 10, 20)}, {{"shadows", "no lights"}});

    const auto passes = table.passes();
    ASSERT_EQ(passes.size(), 3u);
    EXPECT_EQ(passes[0].name, "gbuffer");
    EXPECT_DOUBLE_EQ(passes[0].medianMs, 2.0);
    EXPECT_DOUBLE_EQ(passes[0].minMs, 1.0);
    EXPECT_DOUBLE_EQ(passes[0].maxMs, 3.0);
    EXPECT_EQ(passes[1].name, "light");
    EXPECT_DOUBLE_EQ(passes[1].medianMs, 4.0);
    EXPECT_EQ(passes[2].name, "frame");
    EXPECT_DOUBLE_EQ(passes[2].medianMs, 7.0); // totals 3, 7, 8
    EXPECT_EQ(table.recordedFrames(), 3u);
    ASSERT_EQ(table.skips().size(), 1u);
    EXPECT_EQ(table.skips()[0].reason, "no lights");
}

TEST(TimingTable, NestedRegionsDoNotAddToTheFrameTotal) {
    TimingTable table;
    table.addFrame(
        {timer("gi", 5.0, 0, 50), timer("gi: trace", 3.0, 10, 40), timer("composite", 1.0, 50, 60)});
    EXPECT_DOUBLE_EQ(table.medianFrameMs(), 6.0);
}

TEST(TimingTable, PrintsAndWritesJson) {
    TimingTable table;
    table.addFrame({timer("gbuffer", 1.5, 0, 10)}, {{"point shadows", "no point lights"}});
    std::ostringstream text;
    table.print(text);
    EXPECT_NE(text.str().find("gbuffer"), std::string::npos);
    EXPECT_NE(text.str().find("point shadows: skipped in 1 frame(s), no point lights"), std::string::npos);

    const auto path = std::filesystem::temp_directory_path() / "lumina_timing_table_test.json";
    table.writeJson(path, {{"device", "test"}});
    std::ifstream file(path);
    const std::string json((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_NE(json.find("\"medianMs\": 1.5"), std::string::npos);
    EXPECT_NE(json.find("\"device\": \"test\""), std::string::npos);
    EXPECT_NE(json.find("\"kind\": \"nothing to run\""), std::string::npos);
    std::filesystem::remove(path);
}

// `bench --verify-skips` forces only reuse skips; the kind must survive the aggregation.
TEST(TimingTable, KeepsReuseSkipsApartFromNothingToRun) {
    TimingTable table;
    table.addFrame({}, {{"sun shadows", "unchanged since frame 0", SkipKind::Reuse}});
    table.addFrame({}, {{"sun shadows", "unchanged since frame 0", SkipKind::Reuse}});
    table.addFrame({}, {{"sun shadows", "unchanged since frame 0", SkipKind::NothingToRun}});
    const std::vector<SkipCount> skips = table.skips();
    ASSERT_EQ(skips.size(), 2u);
    const auto reuse = std::ranges::find(skips, SkipKind::Reuse, &SkipCount::kind);
    ASSERT_NE(reuse, skips.end());
    EXPECT_EQ(reuse->frames, 2u);
    const auto none = std::ranges::find(skips, SkipKind::NothingToRun, &SkipCount::kind);
    ASSERT_NE(none, skips.end());
    EXPECT_EQ(none->frames, 1u);
}

} // namespace
} // namespace lumina::gi
