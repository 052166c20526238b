#include "cli/cli_commands.h"

namespace mx::app {
int runLobesCommand(const QStringList&) { return 1; }
}  // namespace mx::app
