#pragma once
// The command-line grammar every `lumina` subcommand shares: global flags, per-command
// flags and positional arguments. A bad flag or value is a UsageError (exit code 2).
#include "rhi/device.h"

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::app {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct FlagSpec {
    std::string_view name;      // without the leading "--"
    std::string_view valueName; // empty: a boolean switch
    std::string_view help;
};

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

// Flags shared by every subcommand.
struct CommonOptions {
    rhi::Api api = rhi::Api::Vulkan;
    uint32_t deviceIndex = 0;
    std::optional<ImageSize> size;
    std::optional<uint32_t> frames;
    std::string out;
    uint64_t seed = 1;
    bool validation = false;
};

class ParsedArgs {
public:
    CommonOptions common;
    std::vector<std::string> positional;

    bool has(std::string_view flag) const { return values_.contains(std::string(flag)); }
    // The value of a flag that takes one; `fallback` when absent.
    std::string get(std::string_view flag, std::string_view fallback = {}) const;
    double getDouble(std::string_view flag, double fallback) const;
    uint64_t getUint(std::string_view flag, uint64_t fallback, uint64_t min = 0,
                     uint64_t max = UINT64_MAX) const;

    void set(std::string_view flag, std::string value) { values_[std::string(flag)] = std::move(value); }

private:
    std::map<std::string, std::string> values_;
};

const std::vector<FlagSpec>& commonFlags();

// Parses `args` (after the subcommand name) against the common flags plus `extra`.
ParsedArgs parseArgs(std::string_view command, const std::vector<std::string>& args,
                     const std::vector<FlagSpec>& extra);

// Strict number parsing with the flag named in the error.
uint64_t parseUint(std::string_view flag, std::string_view text, uint64_t min = 0, uint64_t max = UINT64_MAX);
double parseDouble(std::string_view flag, std::string_view text);
ImageSize parseSize(std::string_view flag, std::string_view text);
// A comma-separated list of at least one non-empty item.
std::vector<std::string> parseList(std::string_view flag, std::string_view text);

} // namespace lumina::app
