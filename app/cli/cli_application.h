#pragma once
#include <QStringList>

#include "services/exit_code.h"

namespace mx::app {

// Dispatches "millexpert-cli SUBCOMMAND ...": prints JSON on stdout, errors on stderr.
int runCli(const QStringList& arguments);

}  // namespace mx::app
