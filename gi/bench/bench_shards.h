#pragma once
// The shards of a bench run (`lumina bench --shard i/n`) and their merge (`lumina merge`).
// A shard writes bench.csv and bench.json for its rows only, as one run would, plus
// shard.json: the run it belongs to (the matrix and the digest of every scene) and the place
// of each of its rows in one run's files. The merge checks that the directories are the n
// shards of one run, each once, on one device, commit and driver, and writes the files one
// run writes (docs/batch.md).
#include "gi/bench/bench_matrix.h"
#include "gi/bench/shard.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::gi {

// Everything that decides which rows a bench run has and what they measure.
struct BenchRunIdentity {
    std::vector<std::string> scenes;
    std::vector<uint64_t> sceneDigests{};
    std::vector<std::string> techniques;
    std::vector<std::string> presets;
    std::vector<double> budgets;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t frames = 0;
    uint32_t referenceSpp = 0;
    uint32_t changeFrames = 0;
};

struct BenchShardManifest {
    BenchRunIdentity run{};
    Shard shard;
    size_t totalRows = 0;
    std::vector<size_t> rows{};       // one run's row of each row of this shard's bench.csv, in order
    std::vector<size_t> changeRows{}; // the same for change_response.csv (the real-time row measured)
};

void writeBenchShardManifest(const std::filesystem::path& directory, const BenchShardManifest& manifest);

struct BenchMergeSummary {
    size_t rows = 0;
    size_t changeRows = 0;
};

// Writes bench.csv, bench.json (and change_response.csv where the shards have one) into
// `out`. std::runtime_error naming the problem: a directory that is no bench shard, a missing
// shard or one given twice, rows claimed twice or by none, shards of different runs, devices,
// drivers or commits.
BenchMergeSummary mergeBenchShards(const std::vector<std::filesystem::path>& shards,
                                   const std::filesystem::path& out);

} // namespace lumina::gi
