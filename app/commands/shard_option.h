#pragma once
// --shard i/n, shared by `lumina reference` and `lumina bench` (docs/batch.md).
#include "app/cli.h"
#include "gi/bench/shard.h"

#include <optional>

namespace lumina::app {

FlagSpec shardFlag(std::string_view help);

// The --shard value, or nothing without the flag; a malformed value is a UsageError.
std::optional<gi::Shard> parseShardFlag(const ParsedArgs& args);

} // namespace lumina::app
