#include "stabilisation_diagram_view.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mx::widgets {

namespace {
constexpr double kMicrometre = 1e6;         // m/N -> µm/N
constexpr double kPickRadiusPx = 10.0;      // a click further from every pole chooses nothing
constexpr double kClusterTolerance = 0.01;  // the stabilisation criterion's frequency tolerance
const QSizeF kNominalScreen(800.0, 500.0);  // for the pick distance before the first layout

QCPGraph* addMarkers(QCustomPlot* plot, const QString& name, const QCPScatterStyle& style) {
  QCPGraph* graph = plot->addGraph(plot->xAxis, plot->yAxis);
  graph->setName(name);
  graph->setLineStyle(QCPGraph::lsNone);
  graph->setScatterStyle(style);
  return graph;
}

bool sameCluster(double a_hz, double b_hz) {
  return std::abs(a_hz - b_hz) <= kClusterTolerance * std::max(a_hz, b_hz);
}

bool samePole(std::complex<double> a, std::complex<double> b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), 1.0);
}
}  // namespace

StabilisationDiagramView::StabilisationDiagramView(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  setMinimumSize(380, 260);
  plot_->setToolTip(
      tr("Click a pole to choose it for the fit, click it again to take it back; one pole per 1 % "
         "frequency cluster."));
  const QFont label_font(font().family(), 10);
  plot_->xAxis->setLabel(tr("Frequency [Hz]"));
  plot_->yAxis->setLabel(tr("Model order [\u2013]"));
  plot_->yAxis2->setLabel(tr("\u03a3 |H| [\u00b5m/N]"));
  plot_->yAxis2->setVisible(true);
  plot_->yAxis2->setScaleType(QCPAxis::stLogarithmic);
  plot_->yAxis2->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
  plot_->yAxis2->setNumberFormat(QStringLiteral("gb"));
  for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis, plot_->yAxis2}) axis->setLabelFont(label_font);

  magnitude_ = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
  magnitude_->setName(tr("\u03a3 |H| measured"));
  magnitude_->setPen(QPen(QColor(150, 150, 150), 1.2));
  stable_ = addMarkers(plot_, tr("stable"),
                       QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(44, 160, 44), QColor(44, 160, 44), 7));
  frequency_stable_ =
      addMarkers(plot_, tr("frequency-stable"),
                 QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(31, 119, 180), 1.5), Qt::NoBrush, 7));
  unstable_ = addMarkers(plot_, tr("unstable"),
                         QCPScatterStyle(QCPScatterStyle::ssCross, QPen(QColor(214, 39, 40), 1.0), Qt::NoBrush, 5));
  chosen_ = addMarkers(plot_, tr("chosen"),
                       QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(0, 0, 0), 2.5), Qt::NoBrush, 15));

  // The legend in a row below the diagram, not over the poles.
  plot_->axisRect()->insetLayout()->take(plot_->legend);
  plot_->plotLayout()->addElement(1, 0, plot_->legend);
  plot_->plotLayout()->setRowStretchFactor(1, 0.001);
  plot_->legend->setFillOrder(QCPLegend::foColumnsFirst);
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->legend->setBorderPen(Qt::NoPen);

  connect(plot_, &QCustomPlot::mousePress, this, &StabilisationDiagramView::onMousePress);
  clear();
}

void StabilisationDiagramView::clear() {
  setDiagram({}, {}, {});
}

void StabilisationDiagramView::setDiagram(const mx::StabilisationDiagram& diagram,
                                          const std::vector<double>& frequency_hz,
                                          const std::vector<double>& summed_magnitude_m_per_n) {
  poles_.clear();
  selected_.clear();
  QVector<double> f[3], order[3];
  double f_lo = std::numeric_limits<double>::infinity(), f_hi = -f_lo;
  int max_order = 0;
  for (const DiagramOrder& o : diagram.orders) {
    max_order = std::max(max_order, o.order);
    for (const DiagramPole& p : o.poles) {
      const auto k = static_cast<std::size_t>(p.stability);
      f[k] << p.frequency_hz;
      order[k] << o.order;
      poles_.push_back({p.lambda, p.frequency_hz, o.order});
      f_lo = std::min(f_lo, p.frequency_hz);
      f_hi = std::max(f_hi, p.frequency_hz);
    }
  }
  unstable_->setData(f[0], order[0]);
  frequency_stable_->setData(f[1], order[1]);
  stable_->setData(f[2], order[2]);

  QVector<double> mf, mag;
  for (std::size_t i = 0; i < std::min(frequency_hz.size(), summed_magnitude_m_per_n.size()); ++i) {
    if (!(summed_magnitude_m_per_n[i] > 0.0) || !std::isfinite(frequency_hz[i])) continue;
    mf << frequency_hz[i];
    mag << summed_magnitude_m_per_n[i] * kMicrometre;
  }
  magnitude_->setData(mf, mag, true);
  if (!mf.isEmpty()) {
    f_lo = std::min(f_lo, mf.front());
    f_hi = std::max(f_hi, mf.back());
    magnitude_->rescaleValueAxis();
    plot_->yAxis2->scaleRange(1.3);
  }
  if (!(f_lo < f_hi)) {
    f_lo = 0.0;
    f_hi = 1000.0;
  }
  plot_->xAxis->setRange(f_lo, f_hi);
  plot_->yAxis->setRange(0.0, std::max(max_order, 2) + 2.0);
  showSelection();
}

void StabilisationDiagramView::setSelectedPoles(const std::vector<std::complex<double>>& poles) {
  selected_ = poles;
  showSelection();
}

// A ring on every diagram marker of a chosen pole; a pole not on the diagram at the highest order.
void StabilisationDiagramView::showSelection() {
  QVector<double> f, order;
  const double top = plot_->yAxis->range().upper - 2.0;
  for (const auto& lambda : selected_) {
    bool placed = false;
    for (const PlacedPole& p : poles_)
      if (samePole(p.lambda, lambda)) {
        f << p.frequency_hz;
        order << p.order;
        placed = true;
      }
    if (!placed) {
      f << std::abs(lambda) / (2.0 * std::numbers::pi);
      order << top;
    }
  }
  chosen_->setData(f, order);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

QPointF StabilisationDiagramView::toScreen(double frequency_hz, double order) const {
  const QRect rect = plot_->axisRect()->rect();
  if (rect.width() >= 50 && rect.height() >= 50)
    return {plot_->xAxis->coordToPixel(frequency_hz), plot_->yAxis->coordToPixel(order)};
  const QCPRange x = plot_->xAxis->range(), y = plot_->yAxis->range();
  return {(frequency_hz - x.lower) / x.size() * kNominalScreen.width(),
          (y.upper - order) / y.size() * kNominalScreen.height()};
}

bool StabilisationDiagramView::togglePoleNear(double frequency_hz, double order) {
  const QPointF click = toScreen(frequency_hz, order);
  const PlacedPole* nearest = nullptr;
  double best = kPickRadiusPx;
  for (const PlacedPole& p : poles_) {
    const double d = QLineF(click, toScreen(p.frequency_hz, p.order)).length();
    if (d <= best) {
      best = d;
      nearest = &p;
    }
  }
  if (!nearest) return false;
  const auto chosen = std::find_if(selected_.begin(), selected_.end(),
                                   [&](const std::complex<double>& s) { return samePole(s, nearest->lambda); });
  if (chosen != selected_.end()) {
    selected_.erase(chosen);
  } else {
    std::erase_if(selected_, [&](const std::complex<double>& s) {
      return sameCluster(std::abs(s) / (2.0 * std::numbers::pi), nearest->frequency_hz);
    });
    selected_.push_back(nearest->lambda);
    std::sort(selected_.begin(), selected_.end(),
              [](const std::complex<double>& a, const std::complex<double>& b) { return std::abs(a) < std::abs(b); });
  }
  showSelection();
  emit selectionChanged(selected_);
  return true;
}

void StabilisationDiagramView::onMousePress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !plot_->axisRect()->rect().contains(event->pos())) return;
  togglePoleNear(plot_->xAxis->pixelToCoord(event->pos().x()), plot_->yAxis->pixelToCoord(event->pos().y()));
}

int StabilisationDiagramView::markerCount(mx::PoleStability stability) const {
  switch (stability) {
    case PoleStability::Stable:
      return stable_->dataCount();
    case PoleStability::FrequencyStable:
      return frequency_stable_->dataCount();
    case PoleStability::Unstable:
      return unstable_->dataCount();
  }
  return 0;
}

int StabilisationDiagramView::chosenMarkerCount() const {
  return chosen_->dataCount();
}

int StabilisationDiagramView::magnitudePointCount() const {
  return magnitude_->dataCount();
}

QStringList StabilisationDiagramView::legendNames() const {
  QStringList names;
  for (int i = 0; i < plot_->legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i))) names << item->plottable()->name();
  return names;
}

QString StabilisationDiagramView::xAxisLabel() const {
  return plot_->xAxis->label();
}

QString StabilisationDiagramView::yAxisLabel() const {
  return plot_->yAxis->label();
}

QString StabilisationDiagramView::magnitudeAxisLabel() const {
  return plot_->yAxis2->label();
}

}  // namespace mx::widgets
