#include "gi/bench/bench_shards.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace lumina::gi {

namespace {

constexpr const char* kManifestName = "shard.json";
constexpr const char* kKind = "lumina bench shard";

nlohmann::ordered_json identityJson(const BenchRunIdentity& run) {
    return {{"scenes", run.scenes},
            {"scene_digests", run.sceneDigests},
            {"techniques", run.techniques},
            {"presets", run.presets},
            {"pt_budgets", run.budgets},
            {"width", run.width},
            {"height", run.height},
            {"frames", run.frames},
            {"reference_spp", run.referenceSpp},
            {"change_frames", run.changeFrames}};
}

std::vector<std::string> readLines(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot read '" + path.string() + "'");
    }
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

nlohmann::ordered_json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot read '" + path.string() + "'");
    }
    try {
        return nlohmann::ordered_json::parse(in);
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

std::ofstream openShardOutput(const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) {
        throw std::runtime_error("cannot write '" + path.string() + "'");
    }
    return out;
}

// One shard directory, read and checked against itself.
struct ShardFiles {
    std::filesystem::path directory;
    nlohmann::ordered_json manifest;
    std::vector<std::string> csv{}; // header first
    nlohmann::ordered_json json{};
    std::vector<std::string> changeCsv{}; // empty without change_response.csv
};

ShardFiles readShard(const std::filesystem::path& directory) {
    const std::filesystem::path manifestPath = directory / kManifestName;
    if (!std::filesystem::is_regular_file(manifestPath)) {
        throw std::runtime_error("'" + directory.string() + "' is not a bench shard: no " + kManifestName +
                                 " (written by lumina bench --shard)");
    }
    ShardFiles files{.directory = directory, .manifest = readJson(manifestPath)};
    try {
        if (files.manifest.at("kind") != kKind) {
            throw std::runtime_error("not a bench shard description");
        }
        files.csv = readLines(directory / "bench.csv");
        files.json = readJson(directory / "bench.json");
        const size_t rows = files.manifest.at("rows").size();
        if (files.csv.size() != rows + 1 || files.json.at("runs").size() != rows) {
            throw std::runtime_error("bench.csv has " + std::to_string(files.csv.size() - 1) +
                                     " rows and bench.json " + std::to_string(files.json.at("runs").size()) +
                                     ", shard.json lists " + std::to_string(rows));
        }
        const std::filesystem::path change = directory / "change_response.csv";
        if (std::filesystem::exists(change)) {
            files.changeCsv = readLines(change);
        }
        if (!files.manifest.at("change_rows").empty() &&
            files.changeCsv.size() != files.manifest.at("change_rows").size() + 1) {
            throw std::runtime_error("change_response.csv does not hold the rows shard.json lists");
        }
    } catch (const std::exception& e) {
        throw std::runtime_error(manifestPath.string() + ": " + e.what());
    }
    return files;
}

// The first field of `a` and `b` that differs, as "NAME A against B", or empty.
std::string firstDifference(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b) {
    for (const auto& [key, value] : a.items()) {
        if (!b.contains(key) || b.at(key) != value) {
            return key + " " + (b.contains(key) ? b.at(key).dump() : "(none)") + " against " + value.dump();
        }
    }
    return {};
}

} // namespace

void writeBenchShardManifest(const std::filesystem::path& directory, const BenchShardManifest& manifest) {
    const nlohmann::ordered_json json = {{"kind", kKind},
                                         {"run", identityJson(manifest.run)},
                                         {"shard", manifest.shard.index},
                                         {"shards", manifest.shard.count},
                                         {"total_rows", manifest.totalRows},
                                         {"rows", manifest.rows},
                                         {"change_rows", manifest.changeRows}};
    std::ofstream out = openShardOutput(directory / kManifestName);
    out << json.dump(2) << '\n';
}

BenchMergeSummary mergeBenchShards(const std::vector<std::filesystem::path>& directories,
                                   const std::filesystem::path& out) {
    if (directories.empty()) {
        throw std::runtime_error("no shards to merge");
    }
    std::vector<ShardFiles> shards;
    std::map<uint32_t, std::filesystem::path> byIndex;
    for (const std::filesystem::path& directory : directories) {
        shards.push_back(readShard(directory));
        const ShardFiles& shard = shards.back();
        const ShardFiles& first = shards.front();
        const auto index = shard.manifest.at("shard").get<uint32_t>();
        const std::string text = std::to_string(index) + "/" + shard.manifest.at("shards").dump();
        const std::string what = "'" + directory.string() + "' and '" + first.directory.string() + "'";
        std::string difference = firstDifference(first.manifest.at("run"), shard.manifest.at("run"));
        if (difference.empty() && shard.manifest.at("shards") != first.manifest.at("shards")) {
            difference = "shard count " + text + " against " + first.manifest.at("shards").dump();
        }
        if (!difference.empty()) {
            throw std::runtime_error(what + " are shards of different runs: " + difference);
        }
        // Figures from different machines or builds are not one run's, whatever the matrix.
        auto context = first.json.at("context");
        context.erase("date");
        if (const std::string other = firstDifference(context, shard.json.at("context")); !other.empty()) {
            throw std::runtime_error(what + " ran on different machines or builds: " + other);
        }
        if (shard.csv.front() != first.csv.front()) {
            throw std::runtime_error(what + " have different bench.csv columns");
        }
        if (const auto twice = byIndex.find(index); twice != byIndex.end()) {
            throw std::runtime_error(what + " are both shard " + text);
        }
        byIndex.emplace(index, directory);
    }
    const auto count = shards.front().manifest.at("shards").get<uint32_t>();
    for (uint32_t i = 0; i < count; ++i) {
        if (!byIndex.contains(i)) {
            throw std::runtime_error("shard " + std::to_string(i) + "/" + std::to_string(count) +
                                     " is missing (" + std::to_string(byIndex.size()) + " of " +
                                     std::to_string(count) + " given)");
        }
    }

    // Every row of one run exactly once, from whichever shard ran it.
    const auto total = shards.front().manifest.at("total_rows").get<size_t>();
    std::vector<const ShardFiles*> owner(total, nullptr);
    std::vector<size_t> position(total, 0);
    std::map<size_t, std::string> changeLines;
    std::string changeHeader;
    nlohmann::ordered_json json = shards.front().json;
    for (const ShardFiles& shard : shards) {
        const auto rows = shard.manifest.at("rows").get<std::vector<size_t>>();
        for (size_t i = 0; i < rows.size(); ++i) {
            if (rows[i] >= total || owner[rows[i]]) {
                throw std::runtime_error(
                    "row " + std::to_string(rows[i]) + " of '" + shard.directory.string() +
                    (rows[i] >= total ? "' is outside the run's " + std::to_string(total)
                                      : "' is also in '" + owner[rows[i]]->directory.string() + "'"));
            }
            owner[rows[i]] = &shard;
            position[rows[i]] = i;
        }
        const auto changeRows = shard.manifest.at("change_rows").get<std::vector<size_t>>();
        for (size_t i = 0; i < changeRows.size(); ++i) {
            changeHeader = shard.changeCsv.front();
            changeLines[changeRows[i]] = shard.changeCsv[i + 1];
        }
        // One run's date is when it started: the earliest shard's.
        json["context"]["date"] = std::min(json["context"]["date"].get<std::string>(),
                                           shard.json.at("context").at("date").get<std::string>());
    }
    if (const auto missing = std::ranges::find(owner, nullptr); missing != owner.end()) {
        throw std::runtime_error("no shard holds row " + std::to_string(missing - owner.begin()) + " of " +
                                 std::to_string(total));
    }

    std::filesystem::create_directories(out);
    std::ofstream csv = openShardOutput(out / "bench.csv");
    csv << shards.front().csv.front() << '\n';
    json["runs"] = nlohmann::ordered_json::array();
    for (size_t row = 0; row < total; ++row) {
        csv << owner[row]->csv[position[row] + 1] << '\n';
        json["runs"].push_back(owner[row]->json.at("runs").at(position[row]));
    }
    std::ofstream jsonOut = openShardOutput(out / "bench.json");
    jsonOut << json.dump(2) << '\n';
    if (!changeLines.empty()) {
        std::ofstream change = openShardOutput(out / "change_response.csv");
        change << changeHeader << '\n';
        for (const auto& [row, line] : changeLines) {
            change << line << '\n';
        }
    }
    return {.rows = total, .changeRows = changeLines.size()};
}

} // namespace lumina::gi
