#pragma once
// Interactive stability-lobe chart (QCustomPlot stays behind this class): the nominal and margined
// envelopes of the tools, the unstable region of the active tool shaded, the power-limit curve for
// the current feed, the admissible region (below both), and the operating point, which the user
// drags with the left button (live signals), nudges with the arrow keys (Shift snaps to the
// admissible grid), zooms with the wheel and pans with the right button. Beside the plot, the tool
// list (LobeToolPanel) names the tools, the active tool's stability pockets and the limit under the
// cursor; the legend under the plot keys the line styles and regions, so that its size does not grow
// with the library. Each tool has one of 20 distinct colours and, as a second cue, a marker shape.
#include <QColor>
#include <QPair>
#include <QPoint>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>

class QCustomPlot;
class QCPGraph;
class QCPItemTracer;
class QCPItemText;
class QCPTextElement;
class QCPAbstractItem;
class QMouseEvent;

namespace mx::widgets {

class CostMapLayer;
class LobeToolPanel;

struct ToolLobeSeries {
  QString tool_id;
  QString dynamics;  // what the lobes ran on, e.g. "fitted modes (SDM)", "measured FRF (ZOA)"; "" = modes
  QVector<double> speed_rpm;
  QVector<double> nominal_mm;       // delta = 0, alpha = 1; NaN where none below the cap
  QVector<double> margined_mm;      // alpha * delta-lobes (Rule 1); NaN where none below the cap
  QVector<double> measured_mm;      // ZOA on the tap-test FRF beside modal lobes (delta = 0); empty: none
  bool margin_needs_modes = false;  // measured lobes only: delta > 0 could not be applied
};

// LimitExceeded: stable, but over the spindle power or the tool force limit. Marginal: within the
// marginal band of the lobe (StabilityBoundary::verdict), where the lobes and a simulation may disagree.
enum class PointVerdict { Unknown, Stable, Marginal, Unstable, LimitExceeded };

class LobeChartView : public QWidget {
  Q_OBJECT
 public:
  explicit LobeChartView(QWidget* parent = nullptr);
  ~LobeChartView() override;

  void setSeries(const QVector<ToolLobeSeries>& series, double delta_per_s, double alpha);
  void setActiveTool(int index);  // whose unstable region is shaded; -1 = none
  // The title above the plot: the stability model of the active tool (modelLabel); "" hides it.
  void setModelLabel(const QString& text);
  QString modelLabel() const;
  void setToolVisible(const QString& tool_id, bool visible);  // hide or show a tool's lobes
  bool isToolVisible(const QString& tool_id) const { return !hidden_.contains(tool_id); }
  // Depth [mm] where peak power reaches the spindle limit, on the active tool's speeds; empty = none.
  void setPowerLimit(const QVector<double>& depth_mm, const QString& label);
  void setOperatingPoint(double speed_rpm, double depth_mm, PointVerdict verdict);
  // Shift snaps to the grid speed_origin + k speed_step, depth k depth_step (a drag snaps both; the
  // arrow keys move one axis to its next grid line and leave the other alone).
  void setSnapGrid(double speed_origin_rpm, double speed_step_rpm, double depth_step_mm);
  // Display unit of the depth axis: value shown per mm (1 for mm, 1/25.4 for inch). Signals and
  // setters stay in mm.
  void setLengthUnit(double display_per_mm, const QString& suffix);
  // A labelled marker (q*, q**, the Pareto q) in `group`: each feature redraws only its own group.
  void setMarker(const QString& name, double speed_rpm, double depth_mm, const QColor& color,
                 const QString& group = {});
  void clearMarkers();                      // every group
  void clearMarkers(const QString& group);  // the markers of one group
  QStringList markerNames() const;          // the labels of the markers shown, in drawing order
  // Expert overlays: the cost heat map of the selected tool (cost[i * depths + j], NaN =
  // not admissible) and the admissible grid points; lengths in mm.
  void setCostMap(const QVector<double>& speeds_rpm, const QVector<double>& depths_mm, const QVector<double>& cost);
  void setGridPoints(const QVector<double>& speeds_rpm, const QVector<double>& depths_mm);
  void setCostMapVisible(bool visible);
  void setGridVisible(bool visible);
  int costCellCount() const;
  void clear();
  void resetView();
  bool saveImage(const QString& path, int width = 1600, int height = 900);  // .png, .svg or .pdf

  double pointSpeed() const { return point_rpm_; }
  double pointDepth() const { return point_mm_; }
  QPoint pixelFor(double speed_rpm, double depth_mm) const;  // in plotWidget() coordinates
  QWidget* plotWidget() const;
  LobeToolPanel* toolPanel() const { return panel_; }
  // Tool `index`'s colour (20 distinct ones, then again) and marker shape (a QCPScatterStyle shape,
  // 7 of them, so that colour and shape together repeat only after 140 tools).
  static QColor toolColor(int index);
  static int toolShape(int index);
  static constexpr int kDistinctColors = 20;
  // The legend entries: on screen the line styles and regions only; an exported image adds one per
  // shown tool, and grows taller rather than cut the legend off.
  QStringList legendNames() const;
  int exportHeight(int width, int height);  // the height saveImage(width, height) uses

 signals:
  void pointDragged(double speed_rpm, double depth_mm);   // live, during a drag
  void pointReleased(double speed_rpm, double depth_mm);  // drag released or key nudge
  void viewReset();
  void activeToolRequested(int index);  // a click on a tool of the list
  void toolVisibilityChanged(const QString& tool_id, bool visible);

 protected:
  void keyPressEvent(QKeyEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void onMousePress(QMouseEvent* event);
  void onMouseMove(QMouseEvent* event);
  void onMouseRelease(QMouseEvent* event);
  void movePointTo(double speed_rpm, double depth_mm, bool snap_speed, bool snap_depth);
  void updateRegions();
  void applyToolVisibility();
  void updatePockets();
  void showCursorLimit(const QPointF& pixel);
  void addLineStyleKeys(double delta_per_s, double alpha, bool measured);
  void setToolsInLegend(bool shown);
  void fitLegendColumns();
  void placeBelowOtherLabels(QCPItemText* text, double dx);
  bool writeImage(const QString& path, int width, int height);
  void replotOverlay();
  void replotQueued();

  QCustomPlot* plot_;
  CostMapLayer* costs_;
  LobeToolPanel* panel_;
  QVector<double> map_speeds_, map_depths_mm_, map_cost_, grid_speeds_, grid_depths_mm_;
  QCPGraph* unstable_top_ = nullptr;
  QCPGraph* unstable_fill_ = nullptr;
  QCPGraph* admissible_fill_ = nullptr;
  QCPGraph* power_graph_ = nullptr;
  QCPItemTracer* marker_ = nullptr;
  QCPItemText* marker_label_ = nullptr;
  QCPTextElement* title_ = nullptr;
  QVector<std::pair<QString, QCPAbstractItem*>> extra_markers_;  // (group, tracer or label) of q*, q**
  QVector<ToolLobeSeries> series_;
  QVector<QVector<QCPGraph*>> tool_graphs_;  // nominal, margined (, measured FRF) per series
  QSet<QString> hidden_;
  QVector<double> power_mm_;
  int active_ = -1;
  double point_rpm_ = 0.0, point_mm_ = 0.0;
  double snap_origin_rpm_ = 0.0, snap_rpm_ = 100.0, snap_mm_ = 0.05;
  bool dragging_ = false, panning_ = false;
  QPoint pan_start_;
  double pan_x0_ = 0.0, pan_x1_ = 0.0, pan_y0_ = 0.0, pan_y1_ = 0.0;
  double home_x0_ = 0.0, home_x1_ = 1.0, home_y1_ = 1.0;  // y in mm
  double scale_ = 1.0;                                    // display units per mm
  QString unit_ = "mm";
  QVector<double> scaled(const QVector<double>& mm) const;
  double delta_ = 0.0, alpha_ = 1.0;
  PointVerdict verdict_ = PointVerdict::Unknown;
};

}  // namespace mx::widgets
