// lumina: the headless command-line tool. `lumina --help` lists the subcommands.
#include <exception>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/backends.h"
#include "app/command.h"
#include "rhi/error.h"
#include "rhi/out_of_memory_error.h"

namespace lumina::app {
namespace {

constexpr int kExitUsage = 2;

void printFlags(const std::vector<FlagSpec>& flags) {
    for (const FlagSpec& flag : flags) {
        std::string left = "  --" + std::string(flag.name);
        if (!flag.valueName.empty()) {
            left += " " + std::string(flag.valueName);
        }
        std::cout << std::left << std::setw(26) << left << ' ' << flag.help << '\n';
    }
}

void printMainHelp() {
    std::cout << "lumina " LUMINA_VERSION " - real-time dynamic global illumination, measured\n\n"
                 "usage: lumina COMMAND [ARGS] [FLAGS]\n"
                 "       lumina --list-devices [--api vulkan|d3d12]\n"
                 "       lumina --version\n\ncommands:\n";
    for (const Command& command : allCommands()) {
        std::cout << "  " << std::left << std::setw(12) << command.name << ' ' << command.summary << '\n';
    }
    std::cout << "\nflags every command takes:\n";
    printFlags(commonFlags());
    std::cout << "\n`lumina COMMAND --help` describes one command.\n";
}

void printCommandHelp(const Command& command) {
    std::cout << "usage: " << command.usage << "\n\n" << command.description << "\n\n";
    if (!command.flags.empty()) {
        std::cout << "flags:\n";
        printFlags(command.flags);
        std::cout << '\n';
    }
    std::cout << "common flags:\n";
    printFlags(commonFlags());
}

int listDevices(const CommonOptions& options) {
    std::cout << "compiled APIs:";
    for (rhi::Api api : compiledApis()) {
        std::cout << ' ' << rhi::apiName(api);
    }
    std::cout << "\n" << rhi::apiName(options.api) << " adapters:\n";
    const auto adapters = listAdapters(options.api);
    for (const rhi::AdapterInfo& adapter : adapters) {
        std::cout << "  [" << adapter.index << "] " << adapter.name << " (" << rhi::adapterTypeName(adapter.type)
                  << ", API " << adapter.apiVersion << ", driver " << adapter.driver << ", "
                  << adapter.dedicatedMemoryBytes / (1024 * 1024) << " MiB)\n";
    }
    if (adapters.empty()) {
        std::cout << "  none\n";
        return 1;
    }
    return 0;
}

// Flags that answer on their own, whatever the command.
std::optional<int> runGlobalFlags(const ParsedArgs& parsed) {
    if (parsed.has("version")) {
        std::cout << "lumina " LUMINA_VERSION "\n";
        return 0;
    }
    if (parsed.has("list-devices")) {
        return listDevices(parsed.common);
    }
    return std::nullopt;
}

int run(const std::vector<std::string>& args) {
    if (args.empty()) {
        printMainHelp();
        return kExitUsage;
    }
    const std::string& first = args.front();
    for (const Command& command : allCommands()) {
        if (command.name == first) {
            const std::vector<std::string> rest(args.begin() + 1, args.end());
            ParsedArgs parsed = parseArgs(command.name, rest, command.flags);
            if (parsed.has("help")) {
                printCommandHelp(command);
                return 0;
            }
            if (const auto code = runGlobalFlags(parsed)) {
                return *code;
            }
            return command.run(parsed);
        }
    }
    if (first.rfind("--", 0) != 0) {
        throw UsageError("unknown command '" + first + "' (see lumina --help)");
    }
    const ParsedArgs parsed = parseArgs("", args, {});
    if (!parsed.positional.empty()) {
        throw UsageError("unknown command '" + parsed.positional.front() + "' (see lumina --help)");
    }
    if (const auto code = runGlobalFlags(parsed)) {
        return *code;
    }
    printMainHelp();
    return parsed.has("help") ? 0 : kExitUsage;
}

} // namespace
} // namespace lumina::app

int main(int argc, char** argv) {
    try {
        return lumina::app::run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const lumina::app::UsageError& error) {
        std::cerr << "lumina: " << error.what() << '\n';
        return lumina::app::kExitUsage;
    } catch (const lumina::rhi::OutOfMemoryError& error) {
        std::cerr << "lumina: error: " << error.what()
                  << "\n  (a smaller --size, a lower --preset or a smaller scene needs less GPU memory)\n";
        return 1;
    } catch (const lumina::rhi::DeviceLostError& error) {
        std::cerr << "lumina: error: the GPU device was lost: " << error.what() << '\n';
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "lumina: error: " << error.what() << '\n';
        return 1;
    }
}
