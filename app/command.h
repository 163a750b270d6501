#pragma once
// A `lumina` subcommand: its name, help text, extra flags and entry point. Each lives in
// app/commands/<name>_command.cpp and is listed once in app/commands/registry.cpp.
#include <string_view>
#include <vector>

#include "app/cli.h"

namespace lumina::app {

struct Command {
    std::string_view name;
    std::string_view summary;     // one line, for `lumina --help`
    std::string_view usage;       // e.g. "lumina info SCENE"
    std::string_view description; // paragraphs for `lumina NAME --help`
    std::vector<FlagSpec> flags;  // in addition to commonFlags()
    int (*run)(const ParsedArgs& args) = nullptr; // returns the exit code
};

const std::vector<Command>& allCommands();

// Opens the device named by --api/--device (validation on with --validation), printing
// validation messages to stderr. `presentation`: the device will present to windows
// (rhi::DeviceDesc::presentation; the viewer).
rhi::DeviceHandle openDevice(const CommonOptions& options, bool presentation = false);

} // namespace lumina::app
