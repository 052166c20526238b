#pragma once
// What the monkey did, one line per action (its number, time, kind, dock, widget, screen point and
// detail), flushed to the log file as it happens so that the supervisor can print the last ones after a
// crash; and the counts per kind and per dock for the report.
#include <QFile>
#include <QMap>
#include <QPoint>
#include <QString>

namespace mx::e2e {

struct MonkeyAction {
  QString kind;    // click, drag, wheel, key, type, combo, tab, dialog, ...
  QString region;  // the dock's object name, or "central"
  QString target;  // Class#objectName of the widget aimed at
  QPoint at;       // global screen coordinates
  QString detail;  // keys, text, end point
};

class ActionLog {
 public:
  explicit ActionLog(const QString& path);
  bool isOpen() const { return file_.isOpen(); }
  QString path() const { return file_.fileName(); }

  // Numbers and writes the action; `elapsed_ms` since the monkey started.
  int record(const MonkeyAction& action, qint64 elapsed_ms);
  void note(const QString& text, qint64 elapsed_ms);  // a line that is no action (a dialog closed, ...)

  int count() const { return count_; }
  const QMap<QString, int>& perKind() const { return per_kind_; }
  const QMap<QString, int>& perRegion() const { return per_region_; }
  const QString& last() const { return last_; }

 private:
  void write(const QString& line);
  QFile file_;
  int count_ = 0;
  QMap<QString, int> per_kind_, per_region_;
  QString last_;
};

}  // namespace mx::e2e
