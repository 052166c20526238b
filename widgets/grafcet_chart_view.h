#pragma once
// Drawing of a Grafcet chart (the notation of Landers & Ulsoy section 4, after David & Alla):
// steps are numbered boxes (an initial step is a double box) with their name on the left; transitions
// are thick horizontal bars numbered "(n)" on the left with the receptivity on the right; arcs run
// downward, back arcs go up a lane on the left with an arrow; actions are small boxes right of each
// step ("L*" = impulse action). Active steps carry a token (filled circle).
// Automatic layout: levels by a breadth-first search from the initial steps; the transitions leaving
// a step sit side by side under it in the designer's priority order (left first); a step goes under
// the transition that first reaches it. The widget's minimum size is the drawing's (use a scroll area).
#include <QHash>
#include <QList>
#include <QRectF>
#include <QTransform>
#include <QWidget>

#include "grafcet_chart_data.h"
#include "grafcet_chart_layout.h"

class QPainter;

namespace mx::widgets {

class GrafcetChartView : public QWidget {
  Q_OBJECT
 public:
  explicit GrafcetChartView(QWidget* parent = nullptr);

  void setChart(const GrafcetChartData& chart);
  const GrafcetChartData& chart() const { return chart_; }
  void setActiveSteps(const QList<int>& step_ids);  // tokens; unknown ids are ignored
  QList<int> activeSteps() const;
  void setSelected(int step_id, int transition_id);  // highlight (-1: none)
  int selectedStep() const { return selected_step_; }
  int selectedTransition() const { return selected_transition_; }

  // Laid-out geometry in widget coordinates; null rects for unknown ids.
  QRectF stepRect(int step_id) const;
  QRectF transitionRect(int transition_id) const;  // the bar
  bool stepDrawnAsInitial(int step_id) const;      // double box
  bool isBackArc(int transition_id) const;         // drawn upward on a left lane
  QSizeF contentSize() const { return content_; }

  // Fit mode (the supervisor's Run tab): the drawing is scaled down to the widget, never up and never
  // below kMinFitScale, where its labels would become unreadable: the widget's minimum size is the
  // drawing at that scale (put it in a scroll area). Rects, clicks and tooltips follow the scale.
  static constexpr double kMinFitScale = 0.9;
  void setFitToWidget(bool fit);
  bool fitToWidget() const { return fit_; }
  double scale() const;  // of the drawing in the widget
  double smallestLabelPointSize() const { return GrafcetLayout::kSmallestPt * scale(); }

  bool saveImage(const QString& path, int width, int height);  // PNG, white background, fitted
  QSize sizeHint() const override;

 signals:
  void stepClicked(int step_id);
  void transitionClicked(int transition_id);
  void activeStepsChanged(const QList<int>& step_ids);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  bool event(QEvent* event) override;  // tooltips

 private:
  void layoutChart();
  QTransform toWidget() const;
  void paintChart(QPainter& p) const;
  void paintArcs(QPainter& p) const;

  GrafcetChartData chart_;
  GrafcetLayout layout_;
  QList<int> active_;
  int selected_step_ = -1, selected_transition_ = -1;
  QSizeF content_{200, 120};
  bool fit_ = false;
};

}  // namespace mx::widgets
