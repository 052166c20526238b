#include "ternary_picker.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace mx::widgets {

namespace {

constexpr double kSideMargin = 10.0;
const double kSqrt3 = std::sqrt(3.0);

// Clamps to >= 0 and divides by the sum; the rounding residual goes to the largest weight so that
// the sum is 1 to the last bit or two. An all-zero (or non-finite) vector becomes the centre.
TernaryPicker::Weights normalised(TernaryPicker::Weights w) {
  double sum = 0.0;
  for (double& v : w) {
    v = std::isfinite(v) ? std::max(v, 0.0) : 0.0;
    sum += v;
  }
  if (sum <= 0.0) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  for (double& v : w) v /= sum;
  auto largest = std::max_element(w.begin(), w.end());
  *largest += 1.0 - (w[0] + w[1] + w[2]);
  return w;
}

QPointF closestOnSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
  const QPointF ab = b - a;
  const double len2 = QPointF::dotProduct(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

double distance2(const QPointF& a, const QPointF& b) {
  const QPointF d = a - b;
  return QPointF::dotProduct(d, d);
}

}  // namespace

TernaryPicker::TernaryPicker(QWidget* parent) : QWidget(parent) {
  setMouseTracking(false);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  updateToolTip();
}

void TernaryPicker::setWeights(const Weights& weights) {
  weights_ = normalised(weights);
  updateToolTip();
  update();
}

QPointF TernaryPicker::corner(int index) const {
  const double label = fontMetrics().height() + 6.0;
  const double w = std::max(1.0, width() - 2.0 * kSideMargin);
  const double h = std::max(1.0, height() - 2.0 * label);
  const double side = std::min(w, h * 2.0 / kSqrt3);
  const double tri_h = side * kSqrt3 / 2.0;
  const double cx = width() / 2.0;
  const double top = label + (h - tri_h) / 2.0;
  switch (index) {
    case 0:
      return {cx - side / 2.0, top + tri_h};
    case 1:
      return {cx + side / 2.0, top + tri_h};
    default:
      return {cx, top};
  }
}

QPointF TernaryPicker::pointFor(const Weights& weights) const {
  return weights[0] * corner(0) + weights[1] * corner(1) + weights[2] * corner(2);
}

TernaryPicker::Weights TernaryPicker::weightsAt(const QPointF& point) const {
  const QPointF a = corner(0), b = corner(1), c = corner(2);
  auto barycentric = [&](const QPointF& p) -> Weights {
    const QPointF v0 = b - a, v1 = c - a, v2 = p - a;
    const double den = v0.x() * v1.y() - v1.x() * v0.y();
    if (std::abs(den) < 1e-12) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
    const double l1 = (v2.x() * v1.y() - v1.x() * v2.y()) / den;
    const double l2 = (v0.x() * v2.y() - v2.x() * v0.y()) / den;
    return {1.0 - l1 - l2, l1, l2};
  };
  Weights w = barycentric(point);
  if (std::min({w[0], w[1], w[2]}) < 0.0) {  // outside: the nearest point of the boundary
    const QPointF candidates[] = {closestOnSegment(point, a, b), closestOnSegment(point, b, c),
                                  closestOnSegment(point, c, a)};
    const QPointF* best =
        std::min_element(std::begin(candidates), std::end(candidates),
                         [&](const QPointF& x, const QPointF& y) { return distance2(point, x) < distance2(point, y); });
    w = barycentric(*best);
  }
  return normalised(w);
}

void TernaryPicker::moveTo(const QPointF& point) {
  const Weights w = weightsAt(point);
  if (w == weights_) return;
  weights_ = w;
  updateToolTip();
  update();
  emit weightsChanged(weights_);
}

void TernaryPicker::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
  dragging_ = true;
  moveTo(event->position());
  event->accept();
}

void TernaryPicker::mouseMoveEvent(QMouseEvent* event) {
  if (!dragging_) return QWidget::mouseMoveEvent(event);
  moveTo(event->position());
  event->accept();
}

void TernaryPicker::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !dragging_) return QWidget::mouseReleaseEvent(event);
  moveTo(event->position());
  dragging_ = false;
  emit weightsCommitted(weights_);
  event->accept();
}

void TernaryPicker::updateToolTip() {
  setToolTip(tr("Tool-cost weights c (eq. 13): click or drag inside the triangle to set all three.\n"
                "Corners: c1 (power), c2 (MRR), c3 (\u0394N_s); grid lines every 0.1.\n"
                "Now: c1 = %1, c2 = %2, c3 = %3")
                 .arg(weights_[0], 0, 'f', 3)
                 .arg(weights_[1], 0, 'f', 3)
                 .arg(weights_[2], 0, 'f', 3));
}

void TernaryPicker::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPointF a = corner(0), b = corner(1), c = corner(2);
  QPainterPath triangle;
  triangle.moveTo(a);
  triangle.lineTo(b);
  triangle.lineTo(c);
  triangle.closeSubpath();
  p.fillPath(triangle, palette().color(QPalette::Base));

  // Grid: the lines w_i = k / 10 run parallel to the edge opposite corner i.
  QPen grid(palette().color(QPalette::Mid), 0.0, Qt::DotLine);
  p.setPen(grid);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    for (int step = 1; step < 10; ++step) {
      const double v = step / 10.0;
      Weights from{}, to{};
      from[static_cast<std::size_t>(i)] = v;
      from[static_cast<std::size_t>(j)] = 1.0 - v;
      to[static_cast<std::size_t>(i)] = v;
      to[static_cast<std::size_t>(k)] = 1.0 - v;
      p.drawLine(pointFor(from), pointFor(to));
    }
  }
  p.setPen(QPen(palette().color(QPalette::WindowText), 1.5));
  p.drawPath(triangle);

  // Corner labels: c3 above the top corner, c1 and c2 under the base corners.
  const double lh = fontMetrics().height();
  const QString labels[] = {tr("c1 (power)"), tr("c2 (MRR)"), tr("c3 (\u0394N_s)")};
  const double lw = 120.0;
  p.drawText(QRectF(a.x() - kSideMargin, a.y() + 3.0, lw, lh), Qt::AlignLeft | Qt::AlignVCenter, labels[0]);
  p.drawText(QRectF(b.x() + kSideMargin - lw, b.y() + 3.0, lw, lh), Qt::AlignRight | Qt::AlignVCenter, labels[1]);
  p.drawText(QRectF(c.x() - lw / 2.0, c.y() - lh - 3.0, lw, lh), Qt::AlignCenter, labels[2]);

  // Marker at the current weights.
  const QPointF m = pointFor(weights_);
  p.setPen(QPen(Qt::white, 1.5));
  p.setBrush(QColor(200, 30, 30));
  p.drawEllipse(m, 5.5, 5.5);
}

}  // namespace mx::widgets
