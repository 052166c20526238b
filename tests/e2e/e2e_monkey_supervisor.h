#pragma once
// The monkey runs in a child process (this executable again, with MX_MONKEY_LOG naming its action log)
// watched by the parent: a crash, a sanitizer report or a hang past the deadline kills the child before
// it could say what it did, so the parent prints the seed, the replay command and the last actions.
#include <QString>

#include "e2e_monkey_options.h"

namespace mx::e2e {

// In the child: the action log it writes; "" in the parent.
QString monkeyLogPath();

// In the parent: runs the child to its end (or aborts it at the deadline) and returns its exit code
// (1 when it died of a signal).
int superviseMonkey(char** argv, const MonkeyOptions& options);

}  // namespace mx::e2e
