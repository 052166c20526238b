#pragma once
// The closed-loop plots of the adaptive force controller (the paper's figures 9-12), stacked
// on a shared time axis t [s] (dragging or zooming one row moves all; a double click fits the data):
//   (1) force F [N]: reference (steps), model output, plant output at the samples (markers) and between
//       them (thin line), with the depth of cut b [mm] on the right axis;
//   (2) tracking error e = F_p - F_m [N];
//   (3) feed, the control law [mm/s], at the samples and between them, with the feed limit and the changes of the
//       programmed point (N, b) as vertical lines (the Pareto paper's Fig. 6, lower panel);
//   (4) parameter estimates theta [-] (Rows::All only).
// Each row has its legend in a strip above it, never over the data, in as many columns as the width
// holds without cutting a name; entries of hidden graphs (no feed limit, no programme change) are left
// out. Each row's axis rect keeps kMinRowHeight: the widget's minimum height grows with the rows and
// their legends, and a scroll area around it scrolls instead of squashing the rows in a short dock.
// Force, depth and feed are shown in the shop units of setUnits() (the traces come in N, mm and mm/s).
// QCustomPlot stays behind this class.
#include <QHash>
#include <QPointer>
#include <QStringList>
#include <QVector>
#include <QWidget>

#include "control_data.h"
#include "display_units.h"

class QCustomPlot;
class QCPAxis;
class QCPAxisRect;
class QCPGraph;
class QCPLegend;
class QCPMarginGroup;
class QCPTextElement;

namespace mx::widgets {

class ControlPlots : public QWidget {
  Q_OBJECT
 public:
  enum class Rows { All, Responses };        // Responses: force, error and feed (figures 9-12)
  static constexpr int kMinRowHeight = 130;  // px of each row's axis rect

  explicit ControlPlots(Rows rows = Rows::All, QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);  // nullptr: metric
  void setTraces(const ControlTraces& traces);
  void setFeedLimit(double feed_max_mm_s);  // <= 0 or non-finite: no limit line
  void setTitle(const QString& title);      // empty: no title row
  void clear();

  // Points of a named graph: "reference", "model", "force sampled", "force continuous", "depth",
  // "error", "feed", "feed continuous", "feed limit", "changes", "theta <name>"; -1 for an unknown name.
  int graphPointCount(const QString& name) const;
  QStringList graphNames() const;
  int rowCount() const { return static_cast<int>(rects_.size()); }
  QString valueAxisLabel(int row) const;  // left axis label of a row; empty when out of range
  QString timeAxisLabel() const;
  QStringList legendNames(int row) const;
  QPair<double, double> timeRange() const;
  QPair<double, double> valueRange(int row) const;

  bool savePng(const QString& path, int width, int height);
  // Figures 9-12 style export of `traces` (force, error and feed) with an optional title.
  static bool saveResponses(const ControlTraces& traces, double feed_max_mm_s, const QString& path, int width,
                            int height, const QString& title = {}, DisplayUnits* units = nullptr);

 private:
  QCPAxisRect* addRow(const QString& value_label);
  QCPGraph* addGraph(int row, QCPAxis* value_axis, const QString& key, const QString& legend_name, const QPen& pen);
  void refreshLegend(int row);
  int legendsMinimumWidth() const;
  int legendWidth(int plot_width) const;
  bool legendsFit(int plot_width) const;
  void fitLegends(int plot_width);
  void followLayout();
  void relabel();
  void rebuildThetaGraphs(const QStringList& names);
  void fitRanges();
  void syncTime(const QCPAxisRect* source);

  Rows rows_;
  QPointer<DisplayUnits> units_;
  ControlTraces traces_;  // as given (N, mm, mm/s)
  QCustomPlot* plot_;
  QCPMarginGroup* margin_group_;
  QVector<QCPAxisRect*> rects_;
  QVector<QCPLegend*> legends_;
  QVector<QVector<QCPGraph*>> row_graphs_;  // each row's graphs in legend order
  QHash<QString, QCPGraph*> graphs_;
  QVector<QCPGraph*> theta_graphs_;
  QCPTextElement* title_ = nullptr;
  double feed_max_mm_s_ = 0.0;
  bool syncing_ = false;
};

}  // namespace mx::widgets
