#pragma once
// The longest the GUI event loop went without turning: a precise 10 ms timer notes the time between
// its ticks. The driver's own work between two actions (choosing a widget, starting xdotool) is not
// the window's: pause() closes the current interval and resume() starts a new one, so only the time the
// loop was meant to run counts. To say where a gap came from, an application event filter also notes
// the event that ran longest before the next one started (its receiver and type).
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

class QEvent;

namespace mx::e2e {

class GapProbe : public QObject {
 public:
  GapProbe();
  ~GapProbe() override;
  GapProbe(const GapProbe&) = delete;
  GapProbe& operator=(const GapProbe&) = delete;

  void start();
  void stop();
  void pause();
  void resume();

  qint64 longestMs() const { return longest_ms_; }
  qint64 longestPauseMs() const { return longest_pause_ms_; }
  qint64 longestEventMs() const { return longest_event_ms_; }
  QString longestEvent() const;  // "Class#name, Paint event"

 protected:
  bool eventFilter(QObject* receiver, QEvent* event) override;

 private:
  void close(qint64 now);
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 last_ms_ = 0, paused_at_ms_ = 0;
  qint64 longest_ms_ = 0, longest_pause_ms_ = 0;
  bool running_ = false, paused_ = false;
  // The event being handled (class name, object name, type) and the longest so far.
  struct EventNote {
    const char* class_name = nullptr;
    QString object_name;
    int type = 0;
  };
  EventNote current_event_, longest_event_;
  qint64 event_started_ms_ = -1, longest_event_ms_ = 0;
};

}  // namespace mx::e2e
