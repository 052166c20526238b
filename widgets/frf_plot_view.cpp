#include "frf_plot_view.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "frf_interpolation.h"

namespace mx::widgets {

namespace {
constexpr double kMicrometre = 1e6;  // m/N -> µm/N
const QColor kColors[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44), QColor(148, 103, 189)};

QColor directionColor(std::size_t index) {
  return kColors[index % std::size(kColors)];
}

// The direction a label names: its last word ("measured x" -> "x").
QString directionOf(const QString& label) {
  return label.section(QLatin1Char(' '), -1);
}

QCPAxisRect* addPanel(QCustomPlot* plot, QCPMarginGroup* margins, int row) {
  auto* rect = row == 0 ? plot->axisRect() : new QCPAxisRect(plot);
  if (row > 0) plot->plotLayout()->addElement(row, 0, rect);
  rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
  for (QCPAxis* axis : rect->axes()) axis->setLabelFont(QFont(plot->font().family(), 10));
  return rect;
}

void setLogScale(QCPAxis* axis, bool log) {
  axis->setScaleType(log ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
  if (log)
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
  else
    axis->setTicker(QSharedPointer<QCPAxisTicker>::create());
  axis->setNumberFormat(log ? QStringLiteral("gb") : QStringLiteral("g"));
}

// A driving-point receptance lags by 0 .. 180 deg: wrapping at +90 deg instead of +180 deg keeps noise
// around -180 deg (above the last mode) from jumping to +180 deg.
double receptancePhaseDeg(std::complex<double> h) {
  const double deg = std::arg(h) * 180.0 / std::numbers::pi;
  return deg > 90.0 ? deg - 360.0 : deg;
}

bool hasData(const QCPGraph* graph) {
  return graph->dataCount() > 0;
}
}  // namespace

FrfPlotView::FrfPlotView(QWidget* parent)
    : QWidget(parent),
      display_box_(new QComboBox(this)),
      log_box_(new QCheckBox(tr("log frequency"), this)),
      plot_(new QCustomPlot(this)) {
  auto* tools = new QHBoxLayout;
  tools->addWidget(new QLabel(tr("display"), this));
  display_box_->addItem(tr("magnitude / phase"));
  display_box_->addItem(tr("real / imaginary"));
  tools->addWidget(display_box_);
  tools->addWidget(log_box_);
  tools->addStretch();
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(tools);
  layout->addWidget(plot_, 1);
  setMinimumSize(420, 300);

  auto* margins = new QCPMarginGroup(plot_);
  upper_ = addPanel(plot_, margins, 0);
  lower_ = addPanel(plot_, margins, 1);
  residual_ = addPanel(plot_, margins, 2);
  // The legend in a row above the panels, not over the curves.
  upper_->insetLayout()->take(plot_->legend);
  plot_->plotLayout()->insertRow(0);
  plot_->plotLayout()->addElement(0, 0, plot_->legend);
  plot_->plotLayout()->setRowStretchFactors({0.001, 3.0, 2.0, 1.4});
  plot_->legend->setFillOrder(QCPLegend::foColumnsFirst);
  plot_->legend->setBorderPen(Qt::NoPen);
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->legend->setLayer(QStringLiteral("legend"));

  connect(display_box_, &QComboBox::currentIndexChanged, this,
          [this](int index) { setDisplay(index == 1 ? Display::RealImaginary : Display::MagnitudePhase); });
  connect(log_box_, &QCheckBox::toggled, this, &FrfPlotView::setLogFrequency);
  rebuild();
}

void FrfPlotView::setMeasured(const std::vector<FrfCurve>& curves) {
  measured_ = curves;
  rebuild();
}

void FrfPlotView::setFitted(const std::vector<FrfCurve>& curves) {
  fitted_ = curves;
  rebuild();
}

void FrfPlotView::setDisplay(Display display) {
  display_ = display;
  const QSignalBlocker block(display_box_);
  display_box_->setCurrentIndex(display == Display::RealImaginary ? 1 : 0);
  rebuild();
}

void FrfPlotView::setLogFrequency(bool on) {
  const QSignalBlocker block(log_box_);
  log_box_->setChecked(on);
  rebuild();
}

void FrfPlotView::clear() {
  measured_.clear();
  fitted_.clear();
  rebuild();
}

bool FrfPlotView::logFrequency() const {
  return upper_->axis(QCPAxis::atBottom)->scaleType() == QCPAxis::stLogarithmic;
}

const FrfCurve* FrfPlotView::measuredFor(const FrfCurve& fitted, std::size_t index) const {
  for (const FrfCurve& m : measured_)
    if (directionOf(m.label) == directionOf(fitted.label)) return &m;
  return index < measured_.size() ? &measured_[index] : nullptr;
}

void FrfPlotView::rebuild() {
  plot_->clearGraphs();
  residual_graphs_.clear();
  for (std::size_t i = 0; i < measured_.size(); ++i) addCurve(measured_[i], QPen(directionColor(i).lighter(115), 1.8));
  for (std::size_t i = 0; i < fitted_.size(); ++i) {
    const FrfCurve* measured = measuredFor(fitted_[i], i);
    const auto m_index = measured ? static_cast<std::size_t>(measured - measured_.data()) : i;
    // Near-black dashes stay visible where the fit lies on the measurement.
    QPen fitted_pen(directionColor(m_index).darker(300), 1.6);
    fitted_pen.setDashPattern({5.0, 3.0});
    addCurve(fitted_[i], fitted_pen);
    addResidual(fitted_[i], measured ? *measured : FrfCurve{}, QPen(directionColor(m_index), 1.2));
  }
  applyAxes();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void FrfPlotView::addCurve(const FrfCurve& curve, const QPen& pen) {
  const bool log_f = log_box_->isChecked();
  const bool magnitude = display_ == Display::MagnitudePhase;
  QVector<double> f, upper, lower;
  const std::size_t n = std::min(curve.frequency_hz.size(), curve.h_m_per_n.size());
  for (std::size_t k = 0; k < n; ++k) {
    const double hz = curve.frequency_hz[k];
    const std::complex<double> h = curve.h_m_per_n[k] * kMicrometre;
    if (!std::isfinite(hz) || (log_f && hz <= 0.0) || (magnitude && std::abs(h) <= 0.0)) continue;
    f << hz;
    upper << (magnitude ? std::abs(h) : h.real());
    lower << (magnitude ? receptancePhaseDeg(h) : h.imag());
  }
  for (QCPAxisRect* rect : {upper_, lower_}) {
    QCPGraph* graph = plot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    graph->setName(curve.label);
    graph->setPen(pen);
    graph->setData(f, rect == upper_ ? upper : lower, true);
    if (rect == lower_) graph->removeFromLegend();
  }
}

void FrfPlotView::addResidual(const FrfCurve& fitted, const FrfCurve& measured, const QPen& pen) {
  QVector<double> f, r;
  const std::size_t n = std::min(fitted.frequency_hz.size(), fitted.h_m_per_n.size());
  for (std::size_t k = 0; k < n; ++k) {
    const double hz = fitted.frequency_hz[k];
    if (log_box_->isChecked() && hz <= 0.0) continue;
    const auto h = interpolateFrf(measured.frequency_hz, measured.h_m_per_n, hz);
    if (!h) continue;
    f << hz;
    r << std::abs(*h - fitted.h_m_per_n[k]) * kMicrometre;
  }
  QCPGraph* graph = plot_->addGraph(residual_->axis(QCPAxis::atBottom), residual_->axis(QCPAxis::atLeft));
  graph->setName(tr("residual %1").arg(directionOf(fitted.label)));
  graph->setPen(pen);
  graph->setData(f, r, true);
  residual_graphs_.push_back(graph);
}

void FrfPlotView::applyAxes() {
  const bool log_f = log_box_->isChecked();
  const bool magnitude = display_ == Display::MagnitudePhase;
  for (QCPAxisRect* rect : {upper_, lower_, residual_}) {
    setLogScale(rect->axis(QCPAxis::atBottom), log_f);
    rect->axis(QCPAxis::atBottom)->setLabel(tr("Frequency [Hz]"));
  }
  setLogScale(upper_->axis(QCPAxis::atLeft), magnitude);
  upper_->axis(QCPAxis::atLeft)->setLabel(magnitude ? tr("|H| [\u00b5m/N]") : tr("Re H [\u00b5m/N]"));
  lower_->axis(QCPAxis::atLeft)->setLabel(magnitude ? tr("Phase [deg]") : tr("Im H [\u00b5m/N]"));
  residual_->axis(QCPAxis::atLeft)->setLabel(tr("|\u0394H| [\u00b5m/N]"));

  double f_lo = std::numeric_limits<double>::infinity(), f_hi = -f_lo;
  for (int i = 0; i < plot_->graphCount(); ++i) {
    bool found = false;
    const QCPRange keys = plot_->graph(i)->getKeyRange(found, log_f ? QCP::sdPositive : QCP::sdBoth);
    if (!found) continue;
    f_lo = std::min(f_lo, keys.lower);
    f_hi = std::max(f_hi, keys.upper);
  }
  if (!(f_lo < f_hi)) {
    f_lo = log_f ? 10.0 : 0.0;
    f_hi = 1000.0;
  }
  for (QCPAxisRect* rect : {upper_, lower_, residual_}) {
    rect->axis(QCPAxis::atBottom)->setRange(f_lo, f_hi);
    bool first = true;
    for (QCPGraph* graph : rect->graphs()) {
      if (!hasData(graph)) continue;
      graph->rescaleValueAxis(!first, true);
      first = false;
    }
  }
  QCPAxis* residual_axis = residual_->axis(QCPAxis::atLeft);
  residual_axis->ticker()->setTickCount(3);  // the panel is short
  residual_axis->setRange(0.0, std::max(residual_axis->range().upper * 1.1, 1e-6));
  upper_->axis(QCPAxis::atLeft)->scaleRange(1.1);
  lower_->axis(QCPAxis::atLeft)->scaleRange(1.1);
}

int FrfPlotView::upperGraphCount() const {
  const QList<QCPGraph*> graphs = upper_->graphs();
  return static_cast<int>(std::count_if(graphs.cbegin(), graphs.cend(), hasData));
}

int FrfPlotView::lowerGraphCount() const {
  const QList<QCPGraph*> graphs = lower_->graphs();
  return static_cast<int>(std::count_if(graphs.cbegin(), graphs.cend(), hasData));
}

int FrfPlotView::residualGraphCount() const {
  const QList<QCPGraph*> graphs = residual_->graphs();
  return static_cast<int>(std::count_if(graphs.cbegin(), graphs.cend(), hasData));
}

QString FrfPlotView::frequencyAxisLabel() const {
  return upper_->axis(QCPAxis::atBottom)->label();
}

QString FrfPlotView::upperAxisLabel() const {
  return upper_->axis(QCPAxis::atLeft)->label();
}

QString FrfPlotView::lowerAxisLabel() const {
  return lower_->axis(QCPAxis::atLeft)->label();
}

QString FrfPlotView::residualAxisLabel() const {
  return residual_->axis(QCPAxis::atLeft)->label();
}

QStringList FrfPlotView::legendNames() const {
  QStringList names;
  for (int i = 0; i < plot_->legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i))) names << item->plottable()->name();
  return names;
}

std::vector<double> FrfPlotView::lowerPanelValues(int curve_index) const {
  std::vector<double> values;
  const QList<QCPGraph*> graphs = lower_->graphs();
  if (curve_index < 0 || curve_index >= graphs.size()) return values;
  for (const QCPGraphData& point : *graphs[curve_index]->data()) values.push_back(point.value);
  return values;
}

std::vector<double> FrfPlotView::residualFrequencies(int fitted_index) const {
  std::vector<double> f;
  if (fitted_index < 0 || fitted_index >= static_cast<int>(residual_graphs_.size())) return f;
  for (const QCPGraphData& point : *residual_graphs_[static_cast<std::size_t>(fitted_index)]->data())
    f.push_back(point.key);
  return f;
}

std::vector<double> FrfPlotView::residualMicrometrePerNewton(int fitted_index) const {
  std::vector<double> r;
  if (fitted_index < 0 || fitted_index >= static_cast<int>(residual_graphs_.size())) return r;
  for (const QCPGraphData& point : *residual_graphs_[static_cast<std::size_t>(fitted_index)]->data())
    r.push_back(point.value);
  return r;
}

}  // namespace mx::widgets
