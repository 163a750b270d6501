#pragma once
// One part of a batch run split over machines (`--shard i/n`, docs/batch.md): shard i of n
// takes a contiguous band of rows of a reference image, or every n-th unit of the bench's
// matrix; `lumina merge` puts the parts back together.
#include <cstdint>
#include <string>
#include <string_view>

namespace lumina::gi {

struct Shard {
    uint32_t index = 0; // 0-based
    uint32_t count = 1;
    bool whole() const { return count == 1; }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "i/n" with 0 <= i < n; std::invalid_argument naming what is wrong otherwise.
Shard parseShard(std::string_view text);

struct RowBand {
    uint32_t first = 0;
    uint32_t count = 0;
};

// Shard `shard`'s rows of an image `height` rows tall: n bands as equal as whole rows allow,
// in order. std::invalid_argument when there are fewer rows than shards.
RowBand shardRows(uint32_t height, Shard shard);

} // namespace lumina::gi
