#pragma once
// Test helper: the longest the GUI thread spends on one event while the probe runs. A 5 ms ticker
// keeps the loop from idling, so the time from one event's start to the next's is the first event's
// handling time (plus at most the tick). What the test body runs itself is not an event: drive the
// work from timers or input events to have it measured.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QObject>
#include <QString>
#include <QTimer>

namespace mx::test {

class EventLoopProbe : public QObject {
 public:
  EventLoopProbe() {
    ticker_.setInterval(5);
    QObject::connect(&ticker_, &QTimer::timeout, [] {});
    clock_.start();
    QCoreApplication::instance()->installEventFilter(this);
    ticker_.start();
  }
  ~EventLoopProbe() override { QCoreApplication::instance()->removeEventFilter(this); }
  EventLoopProbe(const EventLoopProbe&) = delete;
  EventLoopProbe& operator=(const EventLoopProbe&) = delete;

  qint64 longestMs() const { return longest_ms_; }
  const QString& longestEvent() const { return longest_event_; }  // "Class (objectName) type N"

  bool eventFilter(QObject* receiver, QEvent* event) override {
    const qint64 now = clock_.elapsed();
    if (started_ && now - last_ms_ > longest_ms_) {
      longest_ms_ = now - last_ms_;
      longest_event_ = last_event_;
    }
    started_ = true;
    last_ms_ = now;
    last_event_ = QString("%1 (%2) type %3")
                      .arg(receiver->metaObject()->className(), receiver->objectName())
                      .arg(int(event->type()));
    return false;
  }

 private:
  QTimer ticker_;
  QElapsedTimer clock_;
  bool started_ = false;
  qint64 last_ms_ = 0;
  qint64 longest_ms_ = 0;
  QString last_event_, longest_event_;
};

}  // namespace mx::test
