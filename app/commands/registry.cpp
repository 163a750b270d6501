#include "app/command.h"

namespace lumina::app {

// One line per subcommand; each is defined in its own file beside this one.
Command gpuCheckCommand();
Command benchCommand();
Command compareCommand();
Command infoCommand();
Command sdfCommand();
Command referenceCommand();
Command renderCommand();
Command mergeCommand();

const std::vector<Command>& allCommands() {
    static const std::vector<Command> commands = {
        gpuCheckCommand(), benchCommand(),     compareCommand(), infoCommand(),
        sdfCommand(),      referenceCommand(), renderCommand(),  mergeCommand(),
    };
    return commands;
}

} // namespace lumina::app
