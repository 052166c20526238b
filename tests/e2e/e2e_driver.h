#pragma once
// Real input on the X display. xdotool sends XTEST events: the X server delivers them to the window
// under the pointer (mouse) or with the input focus (keys), as it would a user's mouse and keyboard.
// Coordinates are global (widget->mapToGlobal); the waits process Qt events until a condition holds,
// with a timeout that stops the scenario and names what did not happen.
#include <QPoint>
#include <QSignalSpy>
#include <QString>
#include <QStringList>
#include <functional>
#include <utility>

class QWidget;

namespace mx::e2e {

class XInput {
 public:
  explicit XInput(QString xdotool) : xdotool_(std::move(xdotool)) {}

  void moveTo(QPoint global);  // returns once the pointer is there
  void press();                // left button
  void release();
  void key(const QString& keys);  // xdotool key names, e.g. "ctrl+z"

 private:
  void run(const QStringList& arguments);
  QString xdotool_;
};

// The global position of `local` in `widget`.
QPoint globalPoint(const QWidget* widget, QPoint local);

// Processes events until `done` holds; Aborted naming `what` after `timeout_ms`.
void waitFor(const std::function<bool()>& done, int timeout_ms, const QString& what);
// Until `spy` has recorded more than `seen` signals.
void waitBeyond(const QSignalSpy& spy, qsizetype seen, int timeout_ms, const QString& what);

// Gives `window` the X input focus and waits until Qt reports it active (key events reach it).
void activate(QWidget* window);

}  // namespace mx::e2e
