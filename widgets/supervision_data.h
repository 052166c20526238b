#pragma once
// Display structs of a supervised face-milling run: the traces, the module activity, the
// events and the run's metrics, in display units. The main window converts the engine's results.
#include <QMetaType>
#include <QString>
#include <QVector>
#include <optional>

namespace mx::widgets {

struct SupervisionSeries {  // display units
  QVector<double> t_s, force_y_n /* F_Y */, power_w, feed_mm_s;
  double power_limit_w = 0;
  double force_reference_n = 0;
};

struct ModuleSpan {  // a module (Table 1 letter A-L) active over [from_s, to_s]
  QString module;
  double from_s = 0, to_s = 0;
};

struct SupervisionEventView {
  double t_s = 0;
  QString type;  // e.g. "feed_hold_on", "chatter_detected", "contact", "step"
  QString detail;
};

struct SupervisionMetricsView {
  QString controller;
  double max_power_pct_of_limit = 0, overshoot_pct = 0;
  bool chatter_detected = false;
  std::optional<double> chatter_time_s;
  int passes = 0;
  double cycle_time_s = 0;
  // The force controller's restarts at contact: the longest settling into the 2 % band; unsettled counts
  // the restarts that never settled; no restart: neither.
  std::optional<double> longest_settling_s;
  int unsettled = 0;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::SupervisionSeries)
Q_DECLARE_METATYPE(mx::widgets::SupervisionMetricsView)
