#pragma once
#include <QStringList>

namespace mx::app {

// Exit codes of millexpert-cli (fixed interface).
enum ExitCode : int { kExitOk = 0, kExitComputationFailed = 1, kExitBadInput = 2 };

// Dispatches "millexpert-cli SUBCOMMAND ...": prints JSON on stdout, errors on stderr.
int runCli(const QStringList& arguments);

}  // namespace mx::app
