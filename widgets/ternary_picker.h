#pragma once
// A ternary (simplex) picker for the tool-cost weights c = (c1, c2, c3) of the 2006 cost function
// (eq. 13): an equilateral triangle whose corners are c1 (power, bottom left), c2 (MRR, bottom right)
// and c3 (Delta N_s, top). A point inside is the weight vector given by its barycentric coordinates;
// grid lines every 0.1 and a marker at the current weights. A mouse press or drag moves all three
// weights (points outside are clamped onto the nearest edge); weightsChanged() is emitted live while
// dragging and weightsCommitted() when the mouse is released.
#include <QPointF>
#include <QRectF>
#include <QWidget>
#include <array>

namespace mx::widgets {

class TernaryPicker : public QWidget {
  Q_OBJECT
 public:
  using Weights = std::array<double, 3>;

  explicit TernaryPicker(QWidget* parent = nullptr);

  // Shows `weights` (clamped to >= 0 and renormalised onto the simplex); emits no signal.
  void setWeights(const Weights& weights);
  const Weights& weights() const { return weights_; }

  // Widget coordinates of a weight vector (corners: pointFor({1,0,0}) is the c1 corner) and back:
  // weightsAt() returns the barycentric coordinates of `point`, clamped onto the triangle (the
  // nearest point of its boundary for a point outside), non-negative and summing to 1.
  QPointF pointFor(const Weights& weights) const;
  Weights weightsAt(const QPointF& point) const;
  QPointF corner(int index) const;  // 0: c1, 1: c2, 2: c3

  QSize sizeHint() const override { return {260, 230}; }
  QSize minimumSizeHint() const override { return {160, 140}; }

 signals:
  void weightsChanged(const std::array<double, 3>& weights);    // every user change (live)
  void weightsCommitted(const std::array<double, 3>& weights);  // mouse released after a press

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  void moveTo(const QPointF& point);
  void updateToolTip();

  Weights weights_{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  bool dragging_ = false;
};

}  // namespace mx::widgets
