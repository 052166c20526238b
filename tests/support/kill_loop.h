#pragma once
// Test helper for the crash-safety loops: runs a writer process, stops it at the chosen moment (SIGSTOP,
// so that what is inspected is exactly the state the kill leaves behind), notes the files it holds open
// below a folder and its last progress line, then kills it (SIGKILL: no destructor, no flush).
#include <sys/types.h>
#include <unistd.h>

#include <QByteArray>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QThread>
#include <csignal>

namespace mx::test {

// The files process `pid` holds open below `folder` (/proc/<pid>/fd). An unnamed temporary file
// (QSaveFile uses O_TMPFILE on Linux) shows as "<folder>/#<inode> (deleted)".
inline QStringList openFilesBelow(qint64 pid, const QString& folder) {
  QStringList open;
  const QString fd_dir = QString("/proc/%1/fd").arg(pid);
  const QByteArray prefix = QDir(folder).absolutePath().toLocal8Bit() + '/';
  for (const QString& fd : QDir(fd_dir).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot)) {
    char target[4096];
    const ssize_t n = ::readlink(QString(fd_dir + '/' + fd).toLocal8Bit().constData(), target, sizeof target - 1);
    if (n <= 0) continue;
    const QByteArray path(target, static_cast<qsizetype>(n));
    if (path.startsWith(prefix)) open << QString::fromLocal8Bit(path);
  }
  return open;
}

// Whether process `pid` has ended (a zombie, or gone). QProcess::state() would only tell after its
// events are processed, which a polling loop does not do.
inline bool hasEnded(qint64 pid) {
  QFile stat(QString("/proc/%1/stat").arg(pid));
  if (pid <= 0 || !stat.open(QIODevice::ReadOnly)) return true;
  const QByteArray line = stat.readAll();
  const qsizetype name_end = line.lastIndexOf(')');  // "pid (name) state ..."
  const char state = name_end >= 0 && name_end + 2 < line.size() ? line.at(name_end + 2) : 'X';
  return state == 'Z' || state == 'X';
}

// Polls until `process` holds a file open below `folder`; false when it ended first or after
// `timeout_ms`.
inline bool waitForOpenFileBelow(QProcess& process, const QString& folder, int timeout_ms) {
  const qint64 pid = process.processId();
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < timeout_ms) {
    if (!openFilesBelow(pid, folder).isEmpty()) return true;
    if (hasEnded(pid)) return false;
  }
  return false;
}

// How long [us] `process` holds a file open below `folder`, from the first poll that sees one to the
// first that sees none; -1 when it holds none within `timeout_ms`. The process runs on to its end.
inline qint64 measureOpenMicros(QProcess& process, const QString& folder, int timeout_ms) {
  if (!waitForOpenFileBelow(process, folder, timeout_ms)) return -1;
  QElapsedTimer clock;
  clock.start();
  const qint64 pid = process.processId();
  while (!openFilesBelow(pid, folder).isEmpty() && !hasEnded(pid)) {
  }
  return clock.nsecsElapsed() / 1000;
}

// Busy-waits `us` microseconds: QThread::usleep oversleeps by the scheduler's slack, which would
// shift every kill time by the same amount.
inline void spinFor(qint64 us) {
  QElapsedTimer clock;
  clock.start();
  while (clock.nsecsElapsed() < us * 1000) {
  }
}

struct KillOutcome {
  bool killed = false;     // false: the process finished on its own before the kill
  QStringList open_files;  // below the watched folder, at the kill
  QByteArray last_line;    // the last complete line the process printed before the kill
  QByteArray output;       // all it printed
};

// Reads `process`'s output into `seen` until it holds the line `line`; false when the process ended
// first or after `timeout_ms`.
inline bool waitForLine(QProcess& process, QByteArray& seen, const QByteArray& line, int timeout_ms) {
  QElapsedTimer clock;
  clock.start();
  while (!seen.startsWith(line + '\n') && !seen.contains('\n' + line + '\n')) {
    const int left = timeout_ms - static_cast<int>(clock.elapsed());
    if (left <= 0 || !process.waitForReadyRead(left)) return false;
    seen += process.readAllStandardOutput();
  }
  return true;
}

// Stops `process`, records what it holds open below `folder`, kills it and reaps it. `seen`: what
// was already read from its output.
inline KillOutcome stopAndKill(QProcess& process, const QString& folder, const QByteArray& seen = {}) {
  KillOutcome outcome;
  const qint64 pid = process.processId();
  if (pid > 0 && ::kill(static_cast<pid_t>(pid), SIGSTOP) == 0) {
    outcome.open_files = openFilesBelow(pid, folder);
    ::kill(static_cast<pid_t>(pid), SIGKILL);
  }
  process.waitForFinished(10000);
  outcome.killed = process.exitStatus() == QProcess::CrashExit;
  outcome.output = seen + process.readAllStandardOutput();
  const QList<QByteArray> lines = outcome.output.trimmed().split('\n');
  outcome.last_line = lines.isEmpty() ? QByteArray() : lines.last().trimmed();
  return outcome;
}

// The mean time of one write [us] of a writer that prints "ready", then "begin k" and "end k" around its
// k-th write, measured over its first `writes` writes; the writer is killed afterwards. -1 when it did not
// get there within `timeout_ms`. The kill loops draw their delays over a few writes, so that the kills land
// inside the writes however slow the build (sanitizers) or the machine is.
inline qint64 calibrateWriteMicros(QProcess& process, const QString& folder, int writes, int timeout_ms) {
  QByteArray seen;
  if (!waitForLine(process, seen, "ready", timeout_ms)) return -1;
  QElapsedTimer clock;
  clock.start();
  const bool done = waitForLine(process, seen, "end " + QByteArray::number(writes - 1), timeout_ms);
  const qint64 us = clock.nsecsElapsed() / 1000 / writes;
  stopAndKill(process, folder, seen);
  return done ? us : -1;
}

}  // namespace mx::test
