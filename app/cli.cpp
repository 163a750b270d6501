#include "app/cli.h"

#include "app/backends.h"
#include "rhi/error.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace lumina::app {

namespace {
// Largest image side accepted: beyond this, intermediate buffers exceed any GPU's memory.
constexpr uint64_t kMaxImageSide = 16384;
constexpr uint64_t kMaxFrames = 100'000'000;
} // namespace

const std::vector<FlagSpec>& commonFlags() {
    static const std::vector<FlagSpec> flags = {
        {"help", "", "show this help and exit"},
        {"version", "", "print the version and exit"},
        {"list-devices", "", "list the adapters of --api and exit"},
        {"api", "NAME", "graphics API: vulkan or d3d12 (default vulkan)"},
        {"device", "N", "adapter index from --list-devices (default 0)"},
        {"size", "WxH", "image size in pixels, e.g. 1920x1080"},
        {"frames", "N", "number of frames to run"},
        {"out", "PATH", "output file"},
        {"seed", "N", "random seed (default 1)"},
        {"validation", "", "enable the API's validation layer"},
    };
    return flags;
}

uint64_t parseUint(std::string_view flag, std::string_view text, uint64_t min, uint64_t max) {
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
        throw UsageError("--" + std::string(flag) + ": '" + std::string(text) +
                         "' is not a non-negative integer");
    }
    if (value < min || value > max) {
        throw UsageError("--" + std::string(flag) + ": " + std::string(text) + " is out of range [" +
                         std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return value;
}

double parseDouble(std::string_view flag, std::string_view text) {
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        throw UsageError("--" + std::string(flag) + ": '" + std::string(text) + "' is not a finite number");
    }
    return value;
}

std::vector<std::string> parseList(std::string_view flag, std::string_view text) {
    std::vector<std::string> items;
    std::stringstream stream{std::string(text)};
    for (std::string item; std::getline(stream, item, ',');) {
        if (item.empty()) {
            throw UsageError("--" + std::string(flag) + ": empty item in '" + std::string(text) + "'");
        }
        items.push_back(item);
    }
    if (items.empty()) {
        throw UsageError("--" + std::string(flag) + ": give at least one item");
    }
    return items;
}

ImageSize parseSize(std::string_view flag, std::string_view text) {
    const auto x = text.find('x');
    if (x == std::string_view::npos) {
        throw UsageError("--" + std::string(flag) + ": '" + std::string(text) + "' is not WIDTHxHEIGHT");
    }
    return {static_cast<uint32_t>(parseUint(flag, text.substr(0, x), 1, kMaxImageSide)),
            static_cast<uint32_t>(parseUint(flag, text.substr(x + 1), 1, kMaxImageSide))};
}

std::string ParsedArgs::get(std::string_view flag, std::string_view fallback) const {
    const auto it = values_.find(std::string(flag));
    return it == values_.end() ? std::string(fallback) : it->second;
}

double ParsedArgs::getDouble(std::string_view flag, double fallback) const {
    return has(flag) ? parseDouble(flag, get(flag)) : fallback;
}

uint64_t ParsedArgs::getUint(std::string_view flag, uint64_t fallback, uint64_t min, uint64_t max) const {
    return has(flag) ? parseUint(flag, get(flag), min, max) : fallback;
}

ParsedArgs parseArgs(std::string_view command, const std::vector<std::string>& args,
                     const std::vector<FlagSpec>& extra) {
    auto findSpec = [&](std::string_view name) -> const FlagSpec* {
        for (const auto* list : {&commonFlags(), &extra}) {
            for (const FlagSpec& spec : *list) {
                if (spec.name == name) {
                    return &spec;
                }
            }
        }
        return nullptr;
    };

    // A subcommand's help is `lumina NAME --help`; another tool (lumina-viewer) passes its own name.
    const std::string helpHint = command.empty() ? "lumina --help"
                                 : command.starts_with("lumina")
                                     ? std::string(command) + " --help"
                                     : "lumina " + std::string(command) + " --help";
    ParsedArgs parsed;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg.compare(0, 2, "--") != 0 || arg == "--") {
            if (arg.size() > 1 && arg[0] == '-' && arg != "-") {
                throw UsageError("unknown option '" + arg + "' (options start with --; see " + helpHint +
                                 ")");
            }
            parsed.positional.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        std::optional<std::string> value;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name.resize(eq);
        }
        const FlagSpec* spec = findSpec(name);
        if (!spec) {
            throw UsageError("unknown flag '--" + name + "' (see " + helpHint + ")");
        }
        if (spec->valueName.empty()) {
            if (value) {
                throw UsageError("--" + name + " takes no value");
            }
            parsed.set(name, "1");
            continue;
        }
        if (!value) {
            if (i + 1 >= args.size()) {
                throw UsageError("--" + name + " needs a value (" + std::string(spec->valueName) + ")");
            }
            value = args[++i];
        }
        parsed.set(name, *value);
    }

    CommonOptions& common = parsed.common;
    if (parsed.has("api")) {
        try {
            common.api = parseApi(parsed.get("api"));
        } catch (const rhi::Error& error) {
            throw UsageError(std::string("--api: ") + error.what());
        }
    }
    common.deviceIndex = static_cast<uint32_t>(parsed.getUint("device", 0, 0, 255));
    if (parsed.has("size")) {
        common.size = parseSize("size", parsed.get("size"));
    }
    if (parsed.has("frames")) {
        common.frames = static_cast<uint32_t>(parsed.getUint("frames", 1, 1, kMaxFrames));
    }
    common.out = parsed.get("out");
    common.seed = parsed.getUint("seed", 1);
    common.validation = parsed.has("validation");
    return parsed;
}

} // namespace lumina::app
