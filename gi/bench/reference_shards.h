#pragma once
// The shards of a path-traced reference (`lumina reference --shard i/n`) and their merge
// (`lumina merge`): each shard writes its band of rows as an EXR and, beside it in
// PATH.shard.json, what identifies the run (scene digest, size, samples, seed, bounces,
// AOVs, jitter, commit) and which rows it holds. The merge checks that the files are the n
// shards of one run, each once, and stitches them into the image one unsharded run writes.
// docs/batch.md.
#include "gi/bench/shard.h"
#include "gi/image/image.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::gi {

struct ReferenceShardInfo {
    std::string scene; // its name
    uint64_t sceneDigest = 0;
    uint32_t width = 0; // of the whole image
    uint32_t height = 0;
    uint32_t spp = 0;
    uint32_t seed = 0;
    uint32_t maxBounces = 0;
    bool aovs = false;
    bool jitter = true;
    std::string commit;
    Shard shard;
    RowBand rows;
};

// PATH.shard.json for the shard EXR at PATH.
std::filesystem::path shardInfoPath(const std::filesystem::path& exr);
void writeReferenceShardInfo(const std::filesystem::path& exr, const ReferenceShardInfo& info);
// std::runtime_error naming the file when it is missing or malformed.
ReferenceShardInfo readReferenceShardInfo(const std::filesystem::path& exr);

struct MergedReference {
    image::Image image{};   // the whole image, as one run makes it
    ReferenceShardInfo run; // shard and rows: the whole
};

// std::runtime_error naming the problem: a missing shard, one given twice, shards of
// different runs, or an EXR whose size or channels disagree with its .shard.json.
MergedReference mergeReferenceShards(const std::vector<std::filesystem::path>& exrs);

} // namespace lumina::gi
