#pragma once

namespace mx::app {

// Exit codes of millexpert-cli and millexpert-report (fixed interface).
enum ExitCode : int { kExitOk = 0, kExitComputationFailed = 1, kExitBadInput = 2 };

}  // namespace mx::app
