#pragma once
// Side-by-side comparison of the supervisory controllers: one small plot per controller
// (columns none | SMC I | SMC II: F_Y on the left axis, spindle power P on the right with the power
// limit dashed, in the shop units of setUnits(); the series come in N and W) above a metrics table (rows: max power [%
// of limit], force overshoot [%], chatter detected, chatter time [s], passes, cycle time [s]; columns: the
// controllers). Values over the limit and detected chatter are shown in red. QCustomPlot stays behind this class.
#include <QHash>
#include <QPointer>
#include <QStringList>
#include <QWidget>

#include "display_units.h"
#include "supervision_data.h"

class QCustomPlot;
class QHBoxLayout;
class QTableWidget;

namespace mx::widgets {

class SupervisorComparison : public QWidget {
  Q_OBJECT
 public:
  explicit SupervisorComparison(QWidget* parent = nullptr);

  // controller in none/smc1/smc2 -> column 0/1/2 (another name gets a column of its own)
  void setUnits(DisplayUnits* units);  // nullptr: metric
  void setResult(const QString& controller, const SupervisionSeries& series, const SupervisionMetricsView& metrics);
  void clear();
  int resultCount() const;
  // key: max_power_pct_of_limit, overshoot_pct, chatter_detected, chatter_time_s, passes, cycle_time_s
  QString metricText(const QString& controller, const QString& key) const;
  bool saveImage(const QString& path, int width, int height);

  static QString controllerCaption(const QString& controller);  // "smc1" -> "SMC I (transfer line)"
  static QStringList metricKeys();
  QTableWidget* metricsTable() const { return table_; }
  int plotPointCount(const QString& controller) const;  // F_Y points drawn; -1 when no result

 private:
  struct Result {
    SupervisionSeries series;
    SupervisionMetricsView metrics;
  };
  int columnOf(const QString& controller);
  QCustomPlot* makePlot(const QString& controller);
  void showResult(int column);

  QPointer<DisplayUnits> units_;
  QHBoxLayout* plots_layout_;
  QTableWidget* table_;
  QStringList columns_;
  QVector<QCustomPlot*> plots_;
  QHash<QString, Result> results_;
};

}  // namespace mx::widgets
