#pragma once
// Automatic layout of a Grafcet chart for GrafcetChartView, in drawing coordinates:
// levels by a breadth-first search from the initial steps (then from any step not reached), the
// transitions leaving a step side by side under it in priority order (left first), a step under the
// slot of the transition that reaches it first; back arcs (a target not below the source) each get a
// lane on the left, the highest departure nearest the chart. Also the drawing's shared constants and
// the legend row.
#include <QColor>
#include <QFont>
#include <QHash>
#include <QRectF>
#include <QSizeF>

#include "grafcet_chart_data.h"

class QPainter;

namespace mx::widgets {

struct GrafcetLayout {
  static constexpr double kMargin = 16, kStepW = 48, kStepH = 44, kBarW = 36, kBarH = 6;
  static constexpr double kBarBelowStep = 34, kGapBelowBar = 58, kLaneGap = 14, kHeaderH = 64;
  static constexpr double kLevelH = kStepH + kBarBelowStep + kBarH + kGapBelowBar;
  static constexpr double kNameMaxW = 130, kReceptivityMaxW = 220;
  // Label sizes [pt] at scale 1; the smallest stays at least 9 pt at the view's least scale (0.9).
  static constexpr double kTitlePt = 12, kIdPt = 12, kTextPt = 10.5, kNamePt = 10, kActionPt = 10, kLegendPt = 10;
  static constexpr double kSmallestPt = 10;

  struct Transition {
    QRectF bar;
    bool back = false;
    int lane = -1;        // back arcs: lane index (0 nearest the chart)
    double depart_y = 0;  // back arcs: where the arc turns left under the bar
  };
  QHash<int, QRectF> steps;
  QHash<int, Transition> transitions;
  QSizeF content{760, 120};
  double lanes_left = 0;  // x of lane 0

  double laneX(int lane) const { return lanes_left - lane * kLaneGap; }
  static GrafcetLayout compute(const GrafcetChartData& chart, const QFont& base);

  static QFont font(QFont base, double point_size, bool bold = false, bool italic = false);
  static QColor ink() { return QColor(25, 25, 25); }
  static QColor activeFill() { return QColor(255, 236, 150); }
  static QColor token() { return QColor(200, 30, 30); }
  static QColor backArc() { return QColor(70, 70, 150); }
  static void arrowUp(QPainter& p, QPointF tip);  // filled head in the pen colour
  // The title and the legend row; returns the legend's right end.
  static double paintHeader(QPainter& p, const QFont& base, const QString& title);
};

}  // namespace mx::widgets
