#pragma once
// The supervised run on a shared time axis t [s]:
//   top:    F_Y (left axis) with the force reference F_ref (dashed), spindle power P (right axis) with
//           the power limit (dashed red), in the shop units of setUnits() (the series come in N and W);
//   bottom: module activity, one row per Table 1 letter A-L (a bar where the module is active), and an
//           "Events" row of markers (hover for the time, type and detail); each event also draws a
//           thin vertical line across both rows.
// Dragging or wheel-zooming pans/zooms the time axis of both rows; a double click fits the data.
// QCustomPlot stays behind this class.
#include <QHash>
#include <QPointer>
#include <QVector>
#include <QWidget>

#include "display_units.h"
#include "supervision_data.h"

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;

namespace mx::widgets {

class SupervisionTimeline : public QWidget {
  Q_OBJECT
 public:
  explicit SupervisionTimeline(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);  // nullptr: metric
  void clear();
  void appendSeries(const SupervisionSeries& chunk);  // streaming, rpQueuedReplot
  void setSeries(const SupervisionSeries& all);
  void setModuleSpans(const QVector<ModuleSpan>& spans);
  void appendEvents(const QVector<SupervisionEventView>& events);
  int pointCount() const;
  int spanCount() const;
  int eventCount() const;
  bool saveImage(const QString& path, int width, int height);

  // Tests / callers.
  QStringList moduleRows() const;                    // row labels, top to bottom ("A feedrate routine", …)
  double activeTimeOf(const QString& module) const;  // total span length [s]
  QPair<double, double> timeRange() const;
  QString valueAxisLabel(bool power) const;                      // the force (left) or power (right) axis label
  double valueAxisUpper(bool power) const;                       // the top of that axis, in display units
  QString eventToolTipAt(double t_s, double tolerance_s) const;  // empty when no event there
  static QString moduleCaption(const QString& letter);           // "A feedrate routine"

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QCPGraph* moduleGraph(const QString& module);
  void updateLimitLines();
  void fitRanges();
  void syncTime(QCPAxisRect* source);
  void relabel();
  void rescale();

  QCustomPlot* plot_;
  QCPAxisRect* signals_rect_;
  QCPAxisRect* modules_rect_;
  QCPGraph* force_;
  QCPGraph* reference_;
  QCPGraph* power_;
  QCPGraph* limit_;
  QCPGraph* event_marks_;
  QHash<QString, QCPGraph*> modules_;
  QStringList rows_;
  QVector<ModuleSpan> spans_;
  QVector<SupervisionEventView> events_;
  QVector<QCPItemStraightLine*> event_lines_;
  QPointer<DisplayUnits> units_;
  double force_scale_ = 1.0, power_scale_ = 1.0;  // display units per N and per W of the plotted data
  double power_limit_w_ = 0, force_reference_n_ = 0;
  double force_max_ = 0, power_max_ = 0;
  bool syncing_ = false;
};

}  // namespace mx::widgets
