#pragma once
// Test helper: runs the real millexpert-cli and collects its exit code, JSON output and stderr.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>

namespace mx::test {

struct CliRun {
  int code = -1;   // -1 when the process crashed or timed out
  QByteArray out;  // stdout as written
  QJsonObject json;
  QString err;
};

inline CliRun runCli(const QStringList& args, int timeout_ms = 120000) {
  QProcess p;
  p.start(MX_CLI_PATH, args);
  p.waitForFinished(timeout_ms);
  CliRun r;
  r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  r.out = p.readAllStandardOutput();
  r.json = QJsonDocument::fromJson(r.out).object();
  r.err = QString::fromUtf8(p.readAllStandardError());
  return r;
}

// runCli with its default timeout, as the command tests call it.
inline CliRun cli(const QStringList& args) {
  return runCli(args);
}

}  // namespace mx::test
