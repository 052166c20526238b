#pragma once
// xdotool without blocking the window: each command line runs as a QProcess while the GUI event loop
// turns (the window handles the events as the X server delivers them, and opens its dialogs and menus
// as it would for a user). Chained commands ("mousemove 10 20 click 1") make one action one process.
#include <QObject>
#include <QString>
#include <QStringList>
#include <functional>
#include <utility>

namespace mx::e2e {

class AsyncXInput {
 public:
  explicit AsyncXInput(QString xdotool) : xdotool_(std::move(xdotool)) {}

  // Runs xdotool with `arguments`; returns once it has exited, the event loop running meanwhile.
  // `started` is called once the process runs (the driver's own blocking ends there). Aborted when
  // xdotool fails or takes over `timeout_ms`.
  void run(const QStringList& arguments, const std::function<void()>& started, int timeout_ms = 20000);

 private:
  QString xdotool_;
};

// Runs the event loop for `ms` milliseconds.
void spin(int ms);

}  // namespace mx::e2e
