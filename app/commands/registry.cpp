#include "app/command.h"

namespace lumina::app {

// One line per subcommand; each is defined in its own file beside this one.
Command gpuCheckCommand();
#if LUMINA_HAS_GI // commands that need gi/ libraries; the MinGW cross build has none
Command benchCommand();
Command compareCommand();
Command infoCommand();
Command sdfCommand();
Command referenceCommand();
Command renderCommand();
#endif

const std::vector<Command>& allCommands() {
    static const std::vector<Command> commands = {
        gpuCheckCommand(),
#if LUMINA_HAS_GI
        benchCommand(),
        compareCommand(),
        infoCommand(),
        sdfCommand(),
        referenceCommand(),
        renderCommand(),
#endif
    };
    return commands;
}

} // namespace lumina::app
