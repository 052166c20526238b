#include "e2e_driver.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTest>
#include <QWidget>

#include "e2e_report.h"

namespace mx::e2e {

void XInput::moveTo(QPoint global) {
  run({"mousemove", "--sync", QString::number(global.x()), QString::number(global.y())});
}

void XInput::press() {
  run({"mousedown", "1"});
}

void XInput::release() {
  run({"mouseup", "1"});
}

void XInput::key(const QString& keys) {
  run({"key", keys});
}

void XInput::run(const QStringList& arguments) {
  QProcess process;
  process.start(xdotool_, arguments);
  const bool finished = process.waitForFinished(10000);
  if (!finished || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
    throw Aborted(QString("xdotool %1 failed (%2): %3")
                      .arg(arguments.join(' '), finished ? QString("exit %1").arg(process.exitCode()) : "no answer",
                           QString::fromLocal8Bit(process.readAllStandardError()).trimmed()));
}

QPoint globalPoint(const QWidget* widget, QPoint local) {
  return widget->mapToGlobal(local);
}

void waitFor(const std::function<bool()>& done, int timeout_ms, const QString& what) {
  QElapsedTimer clock;
  clock.start();
  if (!QTest::qWaitFor(done, timeout_ms))
    throw Aborted(QString("timed out after %1 ms waiting for %2").arg(clock.elapsed()).arg(what));
}

void waitBeyond(const QSignalSpy& spy, qsizetype seen, int timeout_ms, const QString& what) {
  waitFor([&spy, seen] { return spy.count() > seen; }, timeout_ms, what);
}

void activate(QWidget* window) {
  window->raise();
  window->activateWindow();
  if (!QTest::qWaitForWindowActive(window, 5000))
    throw Aborted("the window never became active: key events would not reach it");
}

}  // namespace mx::e2e
