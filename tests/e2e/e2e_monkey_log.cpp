#include "e2e_monkey_log.h"

namespace mx::e2e {

namespace {
QString seconds(qint64 ms) {
  return QString::number(ms / 1000.0, 'f', 3);
}
}  // namespace

ActionLog::ActionLog(const QString& path) : file_(path) {
  file_.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text);
}

int ActionLog::record(const MonkeyAction& action, qint64 elapsed_ms) {
  ++count_;
  ++per_kind_[action.kind];
  ++per_region_[action.region];
  QString line = QString("#%1 t=%2s %3 %4 %5 at (%6,%7)")
                     .arg(count_)
                     .arg(seconds(elapsed_ms), action.kind, action.region, action.target)
                     .arg(action.at.x())
                     .arg(action.at.y());
  if (!action.detail.isEmpty()) line += " " + action.detail;
  last_ = line;
  write(line);
  return count_;
}

void ActionLog::note(const QString& text, qint64 elapsed_ms) {
  write(QString("   t=%1s %2").arg(seconds(elapsed_ms), text));
}

void ActionLog::write(const QString& line) {
  if (!file_.isOpen()) return;
  file_.write(line.toUtf8() + '\n');
  file_.flush();
}

}  // namespace mx::e2e
