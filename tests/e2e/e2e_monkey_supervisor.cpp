#include "e2e_monkey_supervisor.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QFile>
#include <QTemporaryDir>
#include <chrono>
#include <cstdio>
#include <thread>

namespace mx::e2e {

namespace {

constexpr const char* kLogVariable = "MX_MONKEY_LOG";
constexpr int kTailLines = 50;
// Start-up, the final save and the second window on top of the monkey's own seconds.
constexpr int kOverheadSeconds = 150;

struct ChildEnd {
  int status = 0;
  bool timed_out = false;
};

// Polls the child until it ends; past `deadline` asks it to abort (a core and a sanitizer stack), then
// kills it.
ChildEnd waitForChild(pid_t child, std::chrono::seconds deadline) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  ChildEnd end;
  int signal_sent = 0;
  Clock::time_point signalled;
  for (;;) {
    const pid_t done = waitpid(child, &end.status, WNOHANG);
    if (done == child || (done < 0 && errno != EINTR)) return end;
    const Clock::time_point now = Clock::now();
    if (signal_sent == 0 && now - started > deadline) {
      end.timed_out = true;
      signal_sent = SIGABRT;
      signalled = now;
      kill(child, SIGABRT);
    } else if (signal_sent == SIGABRT && now - signalled > std::chrono::seconds(20)) {
      signal_sent = SIGKILL;
      kill(child, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

QString describe(const ChildEnd& end, int deadline_s) {
  QString what;
  if (WIFEXITED(end.status))
    what = QString("exit code %1").arg(WEXITSTATUS(end.status));
  else if (WIFSIGNALED(end.status))
    what = QString("killed by signal %1 (%2)").arg(WTERMSIG(end.status)).arg(strsignal(WTERMSIG(end.status)));
  else
    what = "ended abnormally";
  if (end.timed_out) what = QString("no end after %1 s, aborted: %2").arg(deadline_s).arg(what);
  return what;
}

void printTail(const QString& log_path) {
  QFile file(log_path);
  if (!file.open(QIODevice::ReadOnly)) {
    std::fprintf(stdout, "monkey: no action log (%s)\n", qPrintable(log_path));
    return;
  }
  const QList<QByteArray> lines = file.readAll().split('\n');
  QList<QByteArray> actions;  // and the notes between them
  for (const QByteArray& line : lines)
    if (!line.isEmpty()) actions << line;
  const qsizetype first = std::max<qsizetype>(0, actions.size() - kTailLines);
  std::fprintf(stdout, "monkey: the last %d of %d lines of the action log:\n", int(actions.size() - first),
               int(actions.size()));
  for (qsizetype i = first; i < actions.size(); ++i) std::fprintf(stdout, "  %s\n", actions[i].constData());
}

}  // namespace

QString monkeyLogPath() {
  return qEnvironmentVariable(kLogVariable);
}

int superviseMonkey(char** argv, const MonkeyOptions& options) {
  QTemporaryDir folder;
  if (!folder.isValid()) {
    std::fprintf(stderr, "millexpert-e2e: FAIL: no temporary folder for the monkey's log\n");
    return 1;
  }
  const QString log_path = folder.filePath("monkey-actions.log");
  qputenv(kLogVariable, QFile::encodeName(log_path));
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child < 0) {
    std::perror("millexpert-e2e: fork");
    return 1;
  }
  if (child == 0) {
    execv("/proc/self/exe", argv);
    std::perror("millexpert-e2e: exec");
    _exit(127);
  }
  const int deadline_s = (options.seconds + kOverheadSeconds) * MX_TIMING_SCALE;
  const ChildEnd end = waitForChild(child, std::chrono::seconds(deadline_s));
  if (WIFEXITED(end.status) && WEXITSTATUS(end.status) == 0 && !end.timed_out) return 0;
  std::fprintf(stdout, "monkey: FAILED (%s), seed %llu\nmonkey: replay: %s\n", qPrintable(describe(end, deadline_s)),
               static_cast<unsigned long long>(options.seed), qPrintable(options.replayCommand()));
  printTail(log_path);
  std::fflush(stdout);
  return WIFEXITED(end.status) && WEXITSTATUS(end.status) != 0 ? WEXITSTATUS(end.status) : 1;
}

}  // namespace mx::e2e
