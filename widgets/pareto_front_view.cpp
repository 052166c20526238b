#include "pareto_front_view.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mx::widgets {

namespace {

QCPRange paddedRange(double lo, double hi) {
  if (!(lo <= hi)) return QCPRange(0.0, 1.0);
  double span = hi - lo;
  if (span <= 1e-12 * std::max(1.0, std::abs(hi))) span = std::max(std::abs(hi) * 0.1, 1e-6);
  return QCPRange(lo - 0.05 * span, hi + 0.05 * span);
}

}  // namespace

double ParetoFrontView::value(const ParetoPointView& p, Axis axis, const ShopUnits& units) {
  switch (axis) {
    case Axis::Tol:
      return p.tol;
    case Axis::Mrr:
      return units.fromBase(Quantity::RemovalRate, cm3PerMinFromCm3PerS(p.mrr_cm3_s));
    case Axis::Surf:
      return p.surf;
    case Axis::Ros:
      return p.ros;
  }
  return 0.0;
}

QString ParetoFrontView::axisLabel(Axis axis, const ShopUnits& units) {
  switch (axis) {
    case Axis::Tol:
      return tr("TOL tool life [min]");
    case Axis::Mrr:
      return tr("MRR removal rate [%1]").arg(units.symbol(Quantity::RemovalRate));
    case Axis::Surf:
      return tr("SURF roughness [\u00b5m]");
    case Axis::Ros:
      return tr("ROS robustness [\u2013]");
  }
  return {};
}

QString ParetoFrontView::defaultToolTip() {
  return tr(
      "The non-dominated (Pareto) set: no other admissible point is better in every objective. "
      "Click a point to move the operating point and the weights to it.");
}

QString ParetoFrontView::pointToolTip(const ParetoPointView& p, const ShopUnits& units) {
  QString text = tr("N = %1 rpm, b = %2, f_z = %3\nTOL = %4 min, MRR = %5, SURF = %6 \u00b5m, ROS = %7")
                     .arg(p.speed_rpm, 0, 'f', 0)
                     .arg(units.format(Quantity::Length, p.depth_mm))
                     .arg(units.format(Quantity::ChipLoad, p.feed_mm_per_tooth))
                     .arg(p.tol, 0, 'g', 4)
                     .arg(units.format(Quantity::RemovalRate, cm3PerMinFromCm3PerS(p.mrr_cm3_s)))
                     .arg(p.surf, 0, 'g', 4)
                     .arg(p.ros, 0, 'g', 4);
  if (p.weights)
    text += tr("\nweights (TOL, MRR, SURF, ROS) = (%1, %2, %3, %4)")
                .arg((*p.weights)[0], 0, 'g', 3)
                .arg((*p.weights)[1], 0, 'g', 3)
                .arg((*p.weights)[2], 0, 'g', 3)
                .arg((*p.weights)[3], 0, 'g', 3);
  return text + tr("\nClick to select it.");
}

ParetoFrontView::ParetoFrontView(QWidget* parent) : QWidget(parent) {
  x_combo_ = makeCombo("pareto_x_axis", tr("Objective on the horizontal axis"), Axis::Mrr);
  y_combo_ = makeCombo("pareto_y_axis", tr("Objective on the vertical axis"), Axis::Tol);
  colour_combo_ = makeCombo("pareto_colour_axis",
                            tr("Objective shown as the colour of the points (scale on the right)"), Axis::Surf);
  auto* controls = new QHBoxLayout;
  const std::array<std::pair<QString, QComboBox*>, 3> rows{
      {{tr("X:"), x_combo_}, {tr("Y:"), y_combo_}, {tr("Colour:"), colour_combo_}}};
  for (const auto& [text, combo] : rows) {
    auto* label = new QLabel(text, this);
    label->setToolTip(combo->toolTip());
    label->setBuddy(combo);
    controls->addWidget(label);
    controls->addWidget(combo);
  }
  controls->addStretch(1);

  plot_ = new QCustomPlot(this);
  plot_->setObjectName("pareto_plot");
  plot_->setMinimumSize(320, 240);
  plot_->setMouseTracking(true);  // hover tool tips of the points
  plot_->setToolTip(defaultToolTip());
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->legend->setBrush(QColor(255, 255, 255, 220));
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);

  scale_ = new QCPColorScale(plot_);
  scale_->setType(QCPAxis::atRight);
  scale_->setGradient(QCPColorGradient(QCPColorGradient::gpJet));
  plot_->plotLayout()->addElement(0, 1, scale_);
  auto* margins = new QCPMarginGroup(plot_);
  plot_->axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
  scale_->setMarginGroup(QCP::msBottom | QCP::msTop, margins);

  bins_.reserve(kColourBins);
  for (int b = 0; b < kColourBins; ++b) {
    QCPGraph* g = plot_->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->removeFromLegend();
    bins_.push_back(g);
  }
  legend_graph_ = plot_->addGraph();
  legend_graph_->setLineStyle(QCPGraph::lsNone);
  legend_graph_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(90, 90, 90), 8));
  legend_graph_->setName(tr("Non-dominated set"));
  selected_graph_ = plot_->addGraph();
  selected_graph_->setLineStyle(QCPGraph::lsNone);
  selected_graph_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 2.0), Qt::NoBrush, 16));
  selected_graph_->setName(tr("Selected point"));
  connect(plot_, &QCustomPlot::mousePress, this, &ParetoFrontView::onMousePress);
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) {
    const int i = nearestPoint(event->position());
    plot_->setToolTip(i >= 0 ? pointToolTip(points_[i], DisplayUnits::of(units_)) : defaultToolTip());
  });

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addWidget(plot_, 1);
  rebuild();
}

QComboBox* ParetoFrontView::makeCombo(const QString& name, const QString& tip, Axis initial) {
  auto* combo = new QComboBox(this);
  combo->setObjectName(name);
  combo->setToolTip(tip);
  for (Axis a : {Axis::Tol, Axis::Mrr, Axis::Surf, Axis::Ros})
    combo->addItem(axisLabel(a, DisplayUnits::of(units_)), static_cast<int>(a));
  combo->setCurrentIndex(static_cast<int>(initial));
  connect(combo, &QComboBox::currentIndexChanged, this, [this] { rebuild(); });
  return combo;
}

ParetoFrontView::Axis ParetoFrontView::xAxis() const {
  return static_cast<Axis>(x_combo_->currentIndex());
}
ParetoFrontView::Axis ParetoFrontView::yAxis() const {
  return static_cast<Axis>(y_combo_->currentIndex());
}
ParetoFrontView::Axis ParetoFrontView::colourAxis() const {
  return static_cast<Axis>(colour_combo_->currentIndex());
}

void ParetoFrontView::setAxes(Axis x, Axis y, Axis colour) {
  const QSignalBlocker bx(x_combo_), by(y_combo_), bc(colour_combo_);
  x_combo_->setCurrentIndex(static_cast<int>(x));
  y_combo_->setCurrentIndex(static_cast<int>(y));
  colour_combo_->setCurrentIndex(static_cast<int>(colour));
  rebuild();
}

void ParetoFrontView::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &ParetoFrontView::refreshUnits);
}

void ParetoFrontView::refreshUnits() {
  const ShopUnits& units = DisplayUnits::of(units_);
  for (QComboBox* combo : {x_combo_, y_combo_, colour_combo_})
    combo->setItemText(static_cast<int>(Axis::Mrr), axisLabel(Axis::Mrr, units));
  rebuild();
}

void ParetoFrontView::setPoints(const QVector<ParetoPointView>& points) {
  points_ = points;
  if (selected_ >= points_.size()) selected_ = -1;
  rebuild();
}

void ParetoFrontView::setSelectedIndex(int index) {
  selected_ = index >= 0 && index < points_.size() ? index : -1;
  rebuild();
}

QWidget* ParetoFrontView::plotWidget() const {
  return plot_;
}
QString ParetoFrontView::colourScaleLabel() const {
  return scale_->axis()->label();
}
QString ParetoFrontView::xAxisLabel() const {
  return plot_->xAxis->label();
}
QString ParetoFrontView::yAxisLabel() const {
  return plot_->yAxis->label();
}

QPointF ParetoFrontView::plottedValue(int index) const {
  if (index < 0 || index >= points_.size()) return {};
  const ParetoPointView& p = points_[index];
  return {value(p, xAxis(), DisplayUnits::of(units_)), value(p, yAxis(), DisplayUnits::of(units_))};
}

QPoint ParetoFrontView::pixelFor(int index) const {
  if (index < 0 || index >= points_.size()) return {-1, -1};
  const QPointF v = plottedValue(index);
  return QPointF(plot_->xAxis->coordToPixel(v.x()), plot_->yAxis->coordToPixel(v.y())).toPoint();
}

void ParetoFrontView::rebuild() {
  const Axis ax = xAxis(), ay = yAxis(), ac = colourAxis();
  const ShopUnits& units = DisplayUnits::of(units_);
  plot_->xAxis->setLabel(axisLabel(ax, units));
  plot_->yAxis->setLabel(axisLabel(ay, units));
  scale_->axis()->setLabel(axisLabel(ac, units));
  legend_graph_->setName(tr("Non-dominated set (%1 points)").arg(points_.size()));

  constexpr double inf = std::numeric_limits<double>::infinity();
  double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf, clo = inf, chi = -inf;
  for (const ParetoPointView& p : points_) {
    xlo = std::min(xlo, value(p, ax, units)), xhi = std::max(xhi, value(p, ax, units));
    ylo = std::min(ylo, value(p, ay, units)), yhi = std::max(yhi, value(p, ay, units));
    clo = std::min(clo, value(p, ac, units)), chi = std::max(chi, value(p, ac, units));
  }
  const QCPRange colourRange = clo < chi ? QCPRange(clo, chi) : paddedRange(clo, chi);
  scale_->setDataRange(colourRange);
  QCPColorGradient gradient = scale_->gradient();  // color() is non-const in QCustomPlot 2

  QVector<QVector<double>> keys(kColourBins), vals(kColourBins);
  for (const ParetoPointView& p : points_) {
    const double t = (value(p, ac, units) - colourRange.lower) / colourRange.size();
    const int b = std::clamp(static_cast<int>(std::floor(t * kColourBins)), 0, kColourBins - 1);
    keys[b].push_back(value(p, ax, units));
    vals[b].push_back(value(p, ay, units));
  }
  for (int b = 0; b < kColourBins; ++b) {
    const double mid = colourRange.lower + (b + 0.5) / kColourBins * colourRange.size();
    const QColor c = QColor::fromRgb(gradient.color(mid, colourRange));
    bins_[b]->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, c.darker(130), c, 8));
    bins_[b]->setData(keys[b], vals[b]);
  }
  if (selected_ >= 0) {
    const QPointF s = plottedValue(selected_);
    selected_graph_->setData(QVector<double>{s.x()}, QVector<double>{s.y()});
  } else {
    selected_graph_->data()->clear();
  }
  plot_->xAxis->setRange(points_.isEmpty() ? QCPRange(0.0, 1.0) : paddedRange(xlo, xhi));
  plot_->yAxis->setRange(points_.isEmpty() ? QCPRange(0.0, 1.0) : paddedRange(ylo, yhi));
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

int ParetoFrontView::nearestPoint(const QPointF& pixel) const {
  int best = -1;
  double bestD2 = static_cast<double>(kPickRadiusPx) * kPickRadiusPx;
  for (int i = 0; i < points_.size(); ++i) {
    const QPointF v = plottedValue(i);
    const double dx = plot_->xAxis->coordToPixel(v.x()) - pixel.x();
    const double dy = plot_->yAxis->coordToPixel(v.y()) - pixel.y();
    const double d2 = dx * dx + dy * dy;
    if (d2 <= bestD2) bestD2 = d2, best = i;
  }
  return best;
}

void ParetoFrontView::onMousePress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  const int i = nearestPoint(event->position());
  if (i < 0) return;
  setSelectedIndex(i);
  emit pointActivated(points_[i]);
}

}  // namespace mx::widgets
