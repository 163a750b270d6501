#include "gi/bench/reference_shards.h"

#include "gi/image/exr.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace lumina::gi {

namespace {

// Everything that must be equal for two shards to belong to one run, as "field=value" lines.
std::vector<std::pair<std::string, std::string>> runFields(const ReferenceShardInfo& info) {
    return {{"scene", info.scene},
            {"scene digest", std::to_string(info.sceneDigest)},
            {"size", std::to_string(info.width) + "x" + std::to_string(info.height)},
            {"spp", std::to_string(info.spp)},
            {"seed", std::to_string(info.seed)},
            {"max bounces", std::to_string(info.maxBounces)},
            {"aovs", info.aovs ? "on" : "off"},
            {"jitter", info.jitter ? "on" : "off"},
            {"commit", info.commit},
            {"shard count", std::to_string(info.shard.count)}};
}

} // namespace

std::filesystem::path shardInfoPath(const std::filesystem::path& exr) {
    return exr.string() + ".shard.json";
}

void writeReferenceShardInfo(const std::filesystem::path& exr, const ReferenceShardInfo& info) {
    const nlohmann::ordered_json json = {{"kind", "lumina reference shard"},
                                         {"scene", info.scene},
                                         {"scene_digest", info.sceneDigest},
                                         {"width", info.width},
                                         {"height", info.height},
                                         {"spp", info.spp},
                                         {"seed", info.seed},
                                         {"max_bounces", info.maxBounces},
                                         {"aovs", info.aovs},
                                         {"jitter", info.jitter},
                                         {"commit", info.commit},
                                         {"shard", info.shard.index},
                                         {"shards", info.shard.count},
                                         {"first_row", info.rows.first},
                                         {"rows", info.rows.count}};
    const std::filesystem::path path = shardInfoPath(exr);
    std::ofstream out(path);
    out << json.dump(2) << '\n';
    if (!out) {
        throw std::runtime_error("cannot write '" + path.string() + "'");
    }
}

ReferenceShardInfo readReferenceShardInfo(const std::filesystem::path& exr) {
    const std::filesystem::path path = shardInfoPath(exr);
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("'" + exr.string() + "' is not a reference shard: no " + path.string() +
                                 " beside it (written by lumina reference --shard)");
    }
    try {
        const nlohmann::json json = nlohmann::json::parse(in);
        if (json.at("kind") != "lumina reference shard") {
            throw std::runtime_error("not a reference shard description");
        }
        ReferenceShardInfo info;
        info.scene = json.at("scene").get<std::string>();
        info.sceneDigest = json.at("scene_digest").get<uint64_t>();
        info.width = json.at("width").get<uint32_t>();
        info.height = json.at("height").get<uint32_t>();
        info.spp = json.at("spp").get<uint32_t>();
        info.seed = json.at("seed").get<uint32_t>();
        info.maxBounces = json.at("max_bounces").get<uint32_t>();
        info.aovs = json.at("aovs").get<bool>();
        info.jitter = json.at("jitter").get<bool>();
        info.commit = json.at("commit").get<std::string>();
        info.shard = {.index = json.at("shard").get<uint32_t>(), .count = json.at("shards").get<uint32_t>()};
        info.rows = {.first = json.at("first_row").get<uint32_t>(), .count = json.at("rows").get<uint32_t>()};
        if (info.shard.index >= info.shard.count || info.height < info.shard.count) {
            throw std::runtime_error("shard " + info.shard.text() + " of an image " +
                                     std::to_string(info.height) + " rows tall");
        }
        const RowBand expected = shardRows(info.height, info.shard);
        if (info.rows.first != expected.first || info.rows.count != expected.count) {
            throw std::runtime_error("rows " + std::to_string(info.rows.first) + "+" +
                                     std::to_string(info.rows.count) + " are not shard " + info.shard.text() +
                                     "'s");
        }
        return info;
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

MergedReference mergeReferenceShards(const std::vector<std::filesystem::path>& exrs) {
    if (exrs.empty()) {
        throw std::runtime_error("no shards to merge");
    }
    std::map<uint32_t, std::pair<std::filesystem::path, ReferenceShardInfo>> shards;
    const ReferenceShardInfo first = readReferenceShardInfo(exrs.front());
    for (const std::filesystem::path& exr : exrs) {
        const ReferenceShardInfo info = readReferenceShardInfo(exr);
        const auto expected = runFields(first), actual = runFields(info);
        for (size_t i = 0; i < expected.size(); ++i) {
            if (expected[i].second != actual[i].second) {
                throw std::runtime_error("'" + exr.string() + "' and '" + exrs.front().string() +
                                         "' are shards of different runs: " + expected[i].first + " " +
                                         actual[i].second + " against " + expected[i].second);
            }
        }
        if (const auto twice = shards.find(info.shard.index); twice != shards.end()) {
            throw std::runtime_error("'" + exr.string() + "' and '" + twice->second.first.string() +
                                     "' are both shard " + info.shard.text());
        }
        shards.emplace(info.shard.index, std::pair{exr, info});
    }
    for (uint32_t i = 0; i < first.shard.count; ++i) {
        if (!shards.contains(i)) {
            throw std::runtime_error("shard " + Shard{i, first.shard.count}.text() + " is missing (" +
                                     std::to_string(shards.size()) + " of " +
                                     std::to_string(first.shard.count) + " given)");
        }
    }

    MergedReference merged{.run = first};
    merged.run.shard = {};
    merged.run.rows = {.first = 0, .count = first.height};
    for (const auto& [index, entry] : shards) {
        const auto& [exr, info] = entry;
        const image::Image part = image::readExr(exr);
        if (part.width() != info.width || part.height() != info.rows.count) {
            throw std::runtime_error("'" + exr.string() + "' is " + image::sizeString(part) +
                                     ", its .shard.json says " + std::to_string(info.width) + "x" +
                                     std::to_string(info.rows.count));
        }
        if (merged.image.empty()) {
            merged.image = image::Image(info.width, info.height, part.channelNames());
        }
        const std::vector<std::string> names = merged.image.channelNames();
        if (part.channelNames() != names) {
            throw std::runtime_error("'" + exr.string() + "' has other channels than the first shard");
        }
        const size_t offset = size_t(info.rows.first) * info.width;
        for (const std::string& name : names) {
            std::ranges::copy(part.channel(name), merged.image.channel(name).begin() + ptrdiff_t(offset));
        }
    }
    return merged;
}

} // namespace lumina::gi
