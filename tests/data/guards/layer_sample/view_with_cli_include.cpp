// Fixture of layers.guard_detects: a view that reaches up into the CLI.
#include "cli/cli_support.h"
#include "document/project.h"
