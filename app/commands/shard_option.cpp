#include "app/commands/shard_option.h"

#include <stdexcept>

namespace lumina::app {

FlagSpec shardFlag(std::string_view help) {
    return {"shard", "i/n", help};
}

std::optional<gi::Shard> parseShardFlag(const ParsedArgs& args) {
    if (!args.has("shard")) {
        return std::nullopt;
    }
    try {
        return gi::parseShard(args.get("shard"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--shard: ") + e.what());
    }
}

} // namespace lumina::app
