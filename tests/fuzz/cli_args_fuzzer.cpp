// libFuzzer target for the command-line grammar every `lumina` subcommand shares (app/cli.h):
// an input is a command name and its arguments separated by NUL bytes, as the shell would
// hand them to main. They go through parseArgs with the common flags and the scene-loading
// flags (app/commands/scene_options.h), then through sceneLoadOptions. A UsageError is the
// expected answer to bad arguments; anything else (a crash, a sanitizer report, another
// exception) is a bug. The value checks a command does after parsing (e.g. --preset) open a
// device first and are covered by the CLI tests, not here.
#include "app/cli.h"
#include "app/commands/scene_options.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace lumina::app;
    std::vector<std::string> args(1);
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            args.emplace_back();
        } else {
            args.back().push_back(char(data[i]));
        }
    }
    const std::string command = args.front();
    args.erase(args.begin());
    static const std::vector<FlagSpec> flags = withSceneLoadFlags({});
    try {
        const ParsedArgs parsed = parseArgs(command, args, flags);
        (void)sceneLoadOptions(parsed);
    } catch (const UsageError&) {
    }
    return 0;
}
