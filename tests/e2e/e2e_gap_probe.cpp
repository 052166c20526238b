#include "e2e_gap_probe.h"

#include <QCoreApplication>
#include <QEvent>
#include <QMetaEnum>
#include <algorithm>

namespace mx::e2e {

GapProbe::GapProbe() {
  timer_.setTimerType(Qt::PreciseTimer);
  timer_.setInterval(10);
  connect(&timer_, &QTimer::timeout, this, [this] {
    if (!paused_) close(clock_.elapsed());
  });
  QCoreApplication::instance()->installEventFilter(this);
}

GapProbe::~GapProbe() {
  QCoreApplication::instance()->removeEventFilter(this);
}

void GapProbe::start() {
  clock_.start();
  last_ms_ = 0;
  running_ = true;
  paused_ = false;
  timer_.start();
}

void GapProbe::stop() {
  if (running_ && !paused_) close(clock_.elapsed());
  running_ = false;
  event_started_ms_ = -1;
  timer_.stop();
}

void GapProbe::pause() {
  if (!running_ || paused_) return;
  const qint64 now = clock_.elapsed();
  close(now);
  paused_ = true;
  paused_at_ms_ = now;
  event_started_ms_ = -1;
}

void GapProbe::resume() {
  if (!running_ || !paused_) return;
  const qint64 now = clock_.elapsed();
  longest_pause_ms_ = std::max(longest_pause_ms_, now - paused_at_ms_);
  paused_ = false;
  last_ms_ = now;
}

void GapProbe::close(qint64 now) {
  longest_ms_ = std::max(longest_ms_, now - last_ms_);
  last_ms_ = now;
}

bool GapProbe::eventFilter(QObject* receiver, QEvent* event) {
  if (!running_ || paused_) return false;
  const qint64 now = clock_.elapsed();
  if (event_started_ms_ >= 0 && now - event_started_ms_ > longest_event_ms_) {
    longest_event_ms_ = now - event_started_ms_;
    longest_event_ = current_event_;
  }
  event_started_ms_ = now;
  current_event_ = {receiver->metaObject()->className(), receiver->objectName(), int(event->type())};
  return false;
}

QString GapProbe::longestEvent() const {
  if (!longest_event_.class_name) return "none";
  QString name = longest_event_.class_name;
  if (!longest_event_.object_name.isEmpty()) name += "#" + longest_event_.object_name;
  const char* type = QMetaEnum::fromType<QEvent::Type>().valueToKey(longest_event_.type);
  return QString("%1, %2 event").arg(name, type ? QString(type) : QString::number(longest_event_.type));
}

}  // namespace mx::e2e
