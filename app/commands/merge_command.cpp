// `lumina merge OUT SHARD...`: puts the shards of a batch run back together (docs/batch.md).
// Reference shards (EXR files from `lumina reference --shard`) become the EXR one run writes;
// bench shards (directories from `lumina bench --shard`) become one run's bench.csv,
// bench.json, change_response.csv and plot.
#include "app/command.h"
#include "app/commands/bench_plot.h"
#include "gi/bench/bench_shards.h"
#include "gi/bench/reference_shards.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace lumina::app {

namespace {

int mergeReferences(const ParsedArgs& args, const std::filesystem::path& out,
                    const std::vector<std::filesystem::path>& shards) {
    if (args.has("no-plot")) {
        throw UsageError("--no-plot: for bench shards; these are reference shards");
    }
    const gi::MergedReference merged = gi::mergeReferenceShards(shards);
    image::writeExr(out, merged.image);
    std::cout << "merged " << shards.size() << " shards of " << merged.run.scene << " (" << merged.run.width
              << "x" << merged.run.height << ", " << merged.run.spp << " spp, seed " << merged.run.seed
              << ") into " << out.string() << '\n';
    if (args.has("png")) {
        image::writePng(args.get("png"), merged.image);
        std::cout << "wrote " << args.get("png") << '\n';
    }
    return 0;
}

int mergeBench(const ParsedArgs& args, const std::filesystem::path& out,
               const std::vector<std::filesystem::path>& shards) {
    if (args.has("png")) {
        throw UsageError("--png: for reference shards; bench shards get DIR/bench.png");
    }
    const gi::BenchMergeSummary summary = gi::mergeBenchShards(shards, out);
    std::cout << "merged " << shards.size() << " bench shards: " << summary.rows << " rows into "
              << (out / "bench.csv").string() << " and " << (out / "bench.json").string();
    if (summary.changeRows) {
        std::cout << ", " << summary.changeRows << " into " << (out / "change_response.csv").string();
    }
    std::cout << '\n';
    if (!args.has("no-plot") && makeBenchPlot(out / "bench.csv", out / "bench.png")) {
        std::cout << "wrote " << (out / "bench.png").string() << '\n';
    }
    return 0;
}

int runMerge(const ParsedArgs& args) {
    if (args.positional.size() < 2) {
        throw UsageError(
            "merge takes OUT and at least one shard: lumina merge OUT SHARD... (see lumina merge --help)");
    }
    const std::filesystem::path out = args.positional.front();
    std::vector<std::filesystem::path> shards(args.positional.begin() + 1, args.positional.end());
    for (const std::filesystem::path& shard : shards) {
        if (!std::filesystem::exists(shard)) {
            throw UsageError("no shard '" + shard.string() + "'");
        }
    }
    const auto isDirectory = [](const std::filesystem::path& p) { return std::filesystem::is_directory(p); };
    if (std::ranges::all_of(shards, isDirectory)) {
        return mergeBench(args, out, shards);
    }
    if (std::ranges::any_of(shards, isDirectory)) {
        throw UsageError("give either bench shard directories or reference shard EXR files, not both");
    }
    const std::filesystem::path parent = std::filesystem::absolute(out).parent_path();
    if (!std::filesystem::is_directory(parent)) {
        throw UsageError("cannot write '" + out.string() + "': no directory " + parent.string());
    }
    return mergeReferences(args, out, shards);
}

} // namespace

Command mergeCommand() {
    return {
        .name = "merge",
        .summary = "combine the shards of a sharded reference or bench run into what one run writes",
        .usage = "lumina merge OUT SHARD... [--png PATH] [--no-plot]",
        .description =
            "Reference shards: OUT is an EXR, each SHARD an EXR written by `lumina reference --shard i/n` "
            "with its SHARD.shard.json beside it; the bands of rows are stitched into the file one "
            "unsharded run with the same scene, size, spp, seed and bounces writes, byte for byte "
            "(radiance, variance and AOVs). Bench shards: OUT is a directory, each SHARD a directory "
            "written by `lumina bench --shard i/n`; OUT gets bench.csv, bench.json (rows in one run's "
            "order, the date the earliest shard's), change_response.csv when the shards measured one, and "
            "bench.png. Every shard 0..n-1 must be given once, all of one run (the same scenes and scene "
            "contents, matrix, sizes and samples; for the bench also the same device, driver, API and "
            "commit); anything else is an error naming the file and the difference, exit code 1. "
            "docs/batch.md.",
        .flags = {{"png", "PATH", "reference shards: also write a tonemapped PNG preview"},
                  {"no-plot", "", "bench shards: write the CSV and JSON only"}},
        .run = runMerge};
}

} // namespace lumina::app
