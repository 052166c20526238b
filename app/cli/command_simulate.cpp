#include "cli/cli_commands.h"

namespace mx::app {
int runSimulateCommand(const QStringList&) { return 1; }
}  // namespace mx::app
