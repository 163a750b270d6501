#pragma once
// The bench's result files: one CSV row and one JSON object per configuration, both headed by
// what makes the figures reproducible (commit, device, driver, API, reference samples).
// Columns and fields: docs/measurement.md.
#include "gi/bench/technique_runs.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lumina::gi {

struct BenchContext {
    std::string commit;
    std::string device;
    std::string driver;
    std::string api;
    std::string date; // UTC, ISO 8601
    uint32_t referenceSpp = 0;
};

// What the path tracer's frame budgets are multiples of (app/commands/bench_command.cpp).
struct TimeBase {
    std::string technique; // "lumen", "direct", or "pathtracer sample"
    double ms = 0.0;       // its median frame time (one sample's time for the last)
};

struct TimeBudget {
    double multiple = 1.0; // 1: equal time
    TimeBase base;
};

struct BenchRecord {
    std::string scene;
    TechniqueRun run;
    std::string referencePath;
    std::optional<TimeBudget> budget{}; // path tracer only
};

void writeBenchCsv(const std::filesystem::path& path, const BenchContext& context,
                   const std::vector<BenchRecord>& records);
void writeBenchJson(const std::filesystem::path& path, const BenchContext& context,
                    const std::vector<BenchRecord>& records);

// The current time as "2026-11-23T12:34:56Z".
std::string utcTimestamp();

} // namespace lumina::gi
