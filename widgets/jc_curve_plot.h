#pragma once
// The cost J_c(beta) of the adaptive force controller (eq. 34; the paper's figure 13): J_c [N s]
// against beta [-] from a sweep, the beta range where H_beta has a zero outside the unit circle
// (beta < threshold) shaded, the minimising beta starred and the current beta marked (overlay layer).
// Non-finite J_c values (failed runs) are left out. QCustomPlot stays behind this class.
#include <QPair>
#include <QStringList>
#include <QWidget>
#include <optional>

#include "control_data.h"

class QCustomPlot;
class QCPGraph;
class QCPItemRect;
class QCPItemStraightLine;
class QCPItemText;
class QCPItemTracer;

namespace mx::widgets {

class JcCurvePlot : public QWidget {
  Q_OBJECT
 public:
  explicit JcCurvePlot(QWidget* parent = nullptr);

  void setCurve(const JcCurveView& curve);
  void setCurrentBeta(double beta);  // clamped to [-1, 1]; a new beta drops the computed J_c
  // J_c of the closed-loop run at the current beta (ControlMetricsView::jc_n_s); shown on the marker.
  void setComputedJc(std::optional<double> jc_n_s);
  std::optional<double> computedJc() const { return computed_jc_; }
  void clear();

  int pointCount() const;  // finite points of the curve
  double currentBeta() const { return current_beta_; }
  std::optional<double> bestBeta() const;  // the starred beta, if any
  bool regionShaded() const;
  QPair<double, double> shadedRange() const;  // (lower, upper) beta of the shaded region
  QStringList legendNames() const;            // visible legend entries
  QString xAxisLabel() const;
  QString yAxisLabel() const;
  bool savePng(const QString& path, int width, int height);

 private:
  void updateMarker();

  QCustomPlot* plot_;
  QCPGraph* curve_;
  QCPGraph* best_;
  QCPGraph* region_legend_;
  QCPGraph* current_legend_;
  QCPItemRect* region_;
  QCPItemText* region_label_;
  QCPItemStraightLine* current_line_;
  QCPItemTracer* current_point_;
  double threshold_ = -1.0;
  double current_beta_ = 0.0;
  std::optional<double> computed_jc_;
};

}  // namespace mx::widgets
