#include "app/command.h"

namespace lumina::app {

// One line per subcommand; each is defined in its own file beside this one.
Command gpuCheckCommand();

const std::vector<Command>& allCommands() {
    static const std::vector<Command> commands = {
        gpuCheckCommand(),
    };
    return commands;
}

} // namespace lumina::app
