#include "e2e_async_input.h"

#include <QEventLoop>
#include <QProcess>
#include <QTimer>

#include "e2e_report.h"

namespace mx::e2e {

void AsyncXInput::run(const QStringList& arguments, const std::function<void()>& started, int timeout_ms) {
  QProcess process;
  QEventLoop loop;
  QTimer deadline;
  deadline.setSingleShot(true);
  bool timed_out = false;
  QObject::connect(&process, &QProcess::finished, &loop, &QEventLoop::quit);
  QObject::connect(&process, &QProcess::errorOccurred, &loop, &QEventLoop::quit);
  QObject::connect(&deadline, &QTimer::timeout, &loop, [&] {
    timed_out = true;
    loop.quit();
  });
  process.start(xdotool_, arguments);
  if (started) started();
  deadline.start(timeout_ms);
  if (process.state() != QProcess::NotRunning) loop.exec();
  const bool not_started = process.error() == QProcess::FailedToStart;
  if (timed_out || not_started || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
    const QString why = timed_out ? QString("no end after %1 ms").arg(timeout_ms)
                                  : QString("exit %1, %2").arg(process.exitCode()).arg(process.errorString());
    process.kill();
    process.waitForFinished(1000);
    throw Aborted(QString("xdotool %1 failed (%2): %3")
                      .arg(arguments.join(' '), why, QString::fromLocal8Bit(process.readAllStandardError()).trimmed()));
  }
}

void spin(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
  loop.exec();
}

}  // namespace mx::e2e
