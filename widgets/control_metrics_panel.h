#pragma once
// The metrics of a closed-loop run, as text with units: the overshoot at each depth step (undershoot for
// a downward step) [%], the settling time [s], J_c [N s], the largest force and the feed range (shop
// units of setUnits(); the view data stays in N and mm/s), and a red warning when H_beta has an unstable zero. Numbers
// in the C locale, 4 significant digits, "–" when missing or non-finite.
#include <QHash>
#include <QPair>
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>

#include "control_data.h"
#include "display_units.h"

class QLabel;

namespace mx::widgets {

class ControlMetricsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ControlMetricsPanel(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);  // nullptr: metric
  void setMetrics(const ControlMetricsView& m);
  // The depth (from, to) [mm] of each step, to name an overshoot or an undershoot; may be empty.
  void setDepthSteps(const QVector<QPair<double, double>>& from_to_mm);
  void clear();  // every value "–", no warning

  // Displayed text by key: "overshoot", "settling_time", "jc", "max_force", "feed_range", "warning";
  // empty for an unknown key.
  QString valueText(const QString& key) const;
  bool warningShown() const;

  // Depth changes of a depth trace: (from, to) for each change of value.
  static QVector<QPair<double, double>> depthSteps(const QVector<double>& depth_mm);

 private:
  void showOvershoots();
  void relabel();

  QPointer<DisplayUnits> units_;
  std::optional<ControlMetricsView> metrics_;
  QHash<QString, QLabel*> labels_;
  QHash<QString, QLabel*> values_;
  QLabel* warning_;
  QVector<double> overshoot_pct_;
  QVector<QPair<double, double>> steps_;
  bool has_metrics_ = false;
};

}  // namespace mx::widgets
