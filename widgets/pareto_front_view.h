#pragma once
// The Pareto-front view: a scatter of the non-dominated set with two objectives on the
// axes and a third as the colour of the points, each chosen by the user from TOL [min], MRR (shop units),
// SURF [um] and ROS [-]. Clicking a point (the nearest one in pixel space within kPickRadiusPx) selects
// it and emits pointActivated(); the caller moves the operating point and the weights to it.
// The plot library stays behind this class.
#include <QMetaType>
#include <QPoint>
#include <QPointF>
#include <QPointer>
#include <QVector>
#include <QWidget>
#include <array>
#include <optional>

#include "display_units.h"

class QComboBox;
class QCustomPlot;
class QCPColorScale;
class QCPGraph;
class QMouseEvent;

namespace mx::widgets {

// One point of the non-dominated set in display units.
struct ParetoPointView {
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
  double tol = 0.0;                              // tool life [min]
  double mrr_cm3_s = 0.0;                        // material removal rate [cm^3/s]
  double surf = 0.0;                             // surface roughness [um]
  double ros = 0.0;                              // robustness [-]
  std::optional<std::array<double, 4>> weights;  // (TOL, MRR, SURF, ROS) weights selecting it, if known
};

class ParetoFrontView : public QWidget {
  Q_OBJECT
 public:
  enum class Axis { Tol = 0, Mrr = 1, Surf = 2, Ros = 3 };  // the order of the combo boxes
  static constexpr int kPickRadiusPx = 10;
  static constexpr int kColourBins = 64;  // the colour scale is drawn with this many graphs

  explicit ParetoFrontView(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);  // MRR, depth and feed per tooth in shop units; nullptr: metric
  void setPoints(const QVector<ParetoPointView>& points);
  const QVector<ParetoPointView>& points() const { return points_; }

  // Chooses the objectives (also through the combo boxes); no signal.
  void setAxes(Axis x, Axis y, Axis colour);
  Axis xAxis() const;
  Axis yAxis() const;
  Axis colourAxis() const;

  // Marks a point as the current one (-1: none); no signal.
  void setSelectedIndex(int index);
  int selectedIndex() const { return selected_; }

  // The plotted value of an objective and its label, e.g. "MRR removal rate [cm³/min]", in `units`.
  static double value(const ParetoPointView& p, Axis axis, const ShopUnits& units = ShopUnits::metric());
  static QString axisLabel(Axis axis, const ShopUnits& units = ShopUnits::metric());
  static QString pointToolTip(const ParetoPointView& p,  // shown when hovering a point
                              const ShopUnits& units = ShopUnits::metric());

  // Tests: the plotted (x, y) of point `index`, and its pixel in plotWidget() coordinates (valid
  // after the plot has been laid out, i.e. after a replot); (0, 0) / (-1, -1) when out of range.
  QPointF plottedValue(int index) const;
  QPoint pixelFor(int index) const;
  QWidget* plotWidget() const;
  QComboBox* xCombo() const { return x_combo_; }
  QComboBox* yCombo() const { return y_combo_; }
  QComboBox* colourCombo() const { return colour_combo_; }
  QString colourScaleLabel() const;
  QString xAxisLabel() const;
  QString yAxisLabel() const;

 signals:
  void pointActivated(const mx::widgets::ParetoPointView& point);

 private:
  static QString defaultToolTip();
  QComboBox* makeCombo(const QString& name, const QString& tip, Axis initial);
  void rebuild();
  void refreshUnits();
  void onMousePress(QMouseEvent* event);
  int nearestPoint(const QPointF& pixel) const;

  QVector<ParetoPointView> points_;
  QPointer<DisplayUnits> units_;
  int selected_ = -1;
  QCustomPlot* plot_ = nullptr;
  QCPColorScale* scale_ = nullptr;
  QCPGraph* legend_graph_ = nullptr;    // empty graph: the legend entry of the set
  QCPGraph* selected_graph_ = nullptr;  // ring around the selected point
  QVector<QCPGraph*> bins_;
  QComboBox* x_combo_ = nullptr;
  QComboBox* y_combo_ = nullptr;
  QComboBox* colour_combo_ = nullptr;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::ParetoPointView)
