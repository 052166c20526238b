#pragma once
// How the replay driver turns a failing input into a finding that can be replayed: the input being
// run is registered, and when the process dies on it (abort, trap, crash signal, sanitizer report,
// uncaught exception), runs longer than the time limit, or grows past the memory limit, its bytes are
// written to `<artifact dir>/<program>-finding` and the reason is printed; the process then exits
// non-zero. `<program> <that file>` replays it.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>

namespace mx::fuzz {

struct FindingLimits {
  std::chrono::milliseconds per_input{5000};
  std::size_t rss_mb = 2048;
};

// Installs the handlers and starts the watchdog thread; call once, before the first input.
void watchForFindings(const std::filesystem::path& artifact, const FindingLimits& limits);

// The input about to run (its bytes must stay alive until inputDone).
void inputStarted(const std::string& bytes);
void inputDone();

}  // namespace mx::fuzz
