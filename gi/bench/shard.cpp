#include "gi/bench/shard.h"

#include <charconv>
#include <stdexcept>

namespace lumina::gi {

namespace {

bool parseNumber(std::string_view text, uint32_t& value) {
    const char* end = text.data() + text.size();
    const auto [last, error] = std::from_chars(text.data(), end, value);
    return !text.empty() && error == std::errc() && last == end;
}

} // namespace

Shard parseShard(std::string_view text) {
    const size_t slash = text.find('/');
    Shard shard;
    if (slash == std::string_view::npos || !parseNumber(text.substr(0, slash), shard.index) ||
        !parseNumber(text.substr(slash + 1), shard.count)) {
        throw std::invalid_argument("expected i/n (shard i of n, 0-based, e.g. 0/4), got '" +
                                    std::string(text) + "'");
    }
    if (shard.count == 0) {
        throw std::invalid_argument("'" + std::string(text) + "': the shard count must be at least 1");
    }
    if (shard.index >= shard.count) {
        throw std::invalid_argument("'" + std::string(text) +
                                    "': the shard index must be below the count (0.." +
                                    std::to_string(shard.count - 1) + ")");
    }
    return shard;
}

RowBand shardRows(uint32_t height, Shard shard) {
    if (height < shard.count) {
        throw std::invalid_argument("an image of " + std::to_string(height) + " rows cannot be split into " +
                                    std::to_string(shard.count) + " shards");
    }
    const auto boundary = [&](uint32_t i) { return uint32_t(uint64_t(height) * i / shard.count); };
    return {.first = boundary(shard.index), .count = boundary(shard.index + 1) - boundary(shard.index)};
}

} // namespace lumina::gi
