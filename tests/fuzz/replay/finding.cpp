#include "replay/finding.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <thread>

// Present when a sanitizer runtime is linked (the asan preset): called before a report ends the process.
// The name is the runtime's own.
extern "C" void __sanitizer_set_death_callback(  // NOLINT(bugprone-reserved-identifier)
    void (*callback)()) __attribute__((weak));

#if defined(__SANITIZE_ADDRESS__)
#define MX_REPLAY_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MX_REPLAY_ASAN 1
#endif
#endif

namespace mx::fuzz {

namespace {

std::atomic<const char*> g_data{nullptr};
std::atomic<std::size_t> g_size{0};
std::atomic<std::int64_t> g_started_ns{0};  // 0: no input running
char g_artifact[4096];
std::atomic_flag g_reported = ATOMIC_FLAG_INIT;
alignas(16) char g_signal_stack[1 << 16];  // a stack overflow is reported on this one

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Everything below runs in signal handlers too: write(2) only.
void say(const char* text) {
  const ssize_t written = write(STDERR_FILENO, text, std::strlen(text));
  static_cast<void>(written);
}

void saveInput(const char* reason) {
  if (g_reported.test_and_set()) return;
  say("\nreplay: finding: ");
  say(reason);
  say("\n");
  const char* data = g_data.load();
  const std::size_t size = g_size.load();
  if (data == nullptr) {
    say("replay: no input was running\n");
    return;
  }
  const int fd = open(g_artifact, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) {
    say("replay: cannot write the input to ");
    say(g_artifact);
    say("\n");
    return;
  }
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = write(fd, data + done, size - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  close(fd);
  say("replay: the input is in ");
  say(g_artifact);
  say("; run this program on that file to replay it\n");
}

void onSignal(int signo) {
  saveInput(signo == SIGABRT   ? "abort (a broken promise or a failed check; see above)"
            : signo == SIGILL  ? "trap (illegal instruction)"
            : signo == SIGSEGV ? "segmentation fault (a stack overflow or a bad access)"
            : signo == SIGFPE  ? "arithmetic exception"
                               : "bus error");
  std::signal(signo, SIG_DFL);
  std::raise(signo);
}

void onTerminate() {
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      say("replay: uncaught exception: ");
      say(x.what());
      say("\n");
    } catch (...) {
      say("replay: uncaught exception of an unknown type\n");
    }
  }
  std::abort();
}

void onSanitizerDeath() {
  saveInput("sanitizer report above");
}

void installHandlers() {
  stack_t stack{};
  stack.ss_sp = g_signal_stack;
  stack.ss_size = sizeof g_signal_stack;
  sigaltstack(&stack, nullptr);
  struct sigaction action {};
  action.sa_handler = onSignal;
  action.sa_flags = SA_ONSTACK | SA_RESETHAND;
  sigemptyset(&action.sa_mask);
#ifdef MX_REPLAY_ASAN
  const int signals[] = {SIGABRT, SIGILL};  // ASan reports the others and calls onSanitizerDeath
#else
  const int signals[] = {SIGABRT, SIGILL, SIGSEGV, SIGFPE, SIGBUS};
#endif
  for (const int signo : signals) sigaction(signo, &action, nullptr);
  std::set_terminate(onTerminate);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(onSanitizerDeath);
}

std::size_t residentMb() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) / (1024 * 1024);
}

[[noreturn]] void watch(FindingLimits limits) {
  const std::int64_t limitNs = std::chrono::nanoseconds(limits.per_input).count();
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const std::int64_t started = g_started_ns.load();
    if (started != 0 && nowNs() - started > limitNs) {
      const std::string reason = "one input ran over the limit of " + std::to_string(limits.per_input.count()) + " ms";
      saveInput(reason.c_str());
      std::_Exit(1);
    }
    if (const std::size_t mb = residentMb(); mb > limits.rss_mb) {
      const std::string reason =
          "resident memory " + std::to_string(mb) + " MB is over the limit of " + std::to_string(limits.rss_mb) + " MB";
      saveInput(reason.c_str());
      std::_Exit(1);
    }
  }
}

}  // namespace

void watchForFindings(const std::filesystem::path& artifact, const FindingLimits& limits) {
  const std::string path = artifact.string();
  if (path.size() >= sizeof g_artifact) throw std::invalid_argument("artifact path too long: " + path);
  std::memcpy(g_artifact, path.c_str(), path.size() + 1);
  installHandlers();
  std::thread(watch, limits).detach();
}

void inputStarted(const std::string& bytes) {
  g_data.store(bytes.data());
  g_size.store(bytes.size());
  g_started_ns.store(nowNs());
}

void inputDone() {
  g_started_ns.store(0);
  g_data.store(nullptr);
}

}  // namespace mx::fuzz
