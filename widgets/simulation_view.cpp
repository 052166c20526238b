#include "simulation_view.h"

#include <qcustomplot.h>

#include <QGraphicsOpacityEffect>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "glossary.h"
#include "indicator_gauge.h"
#include "plot_legend.h"
#include "spectrum_plot.h"
#include "trace_graph.h"

namespace mx::widgets {

namespace {
constexpr int kSpacing = 8;
constexpr int kLiveSpectrumIntervalMs = 250;
constexpr std::size_t kLiveSpectrumSamples = 8192;
const QColor kXColor(31, 119, 180);
const QColor kYColor(255, 127, 14);
const QColor kForceColor(148, 32, 170);  // saturated purple: apart from x, y and the red limit
constexpr int kForceBandAlpha = 25;      // fainter: its band spans the displacements' too
const QColor kPowerColor(44, 160, 44);
const QColor kLimitColor(214, 39, 40);

QCustomPlot* makePlot(QWidget* parent, const QString& tooltip, int legend_columns) {
  auto* plot = new QCustomPlot(parent);
  plot->setMinimumSize(320, 140);
  plot->legend->setVisible(true);
  plot->legend->setFont(QFont(parent->font().family(), 9));
  placeLegendUnderPlot(plot, legend_columns);      // never over a trace
  plot->legend->setMargins(QMargins(6, 1, 6, 1));  // the dock's height is for the traces
  plot->legend->setRowSpacing(0);
  plot->setToolTip(tooltip);
  // Dense oscillating traces: antialiased wide polylines take seconds per repaint; these stay ~ms.
  plot->setPlottingHint(QCP::phFastPolylines, true);
  plot->setNotAntialiasedElements(QCP::aePlottables);
  return plot;
}

// The kept samples of `v` times `factor`; `lo`/`hi` widen to the values seen.
std::vector<double> plotValues(const RingBuffer<double>& v, double& lo, double& hi, double factor = 1.0) {
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    out[i] = factor * v[i];
    if (std::isfinite(out[i])) {
      lo = std::min(lo, out[i]);
      hi = std::max(hi, out[i]);
    }
  }
  return out;
}

QString verdictStyle(const QColor& color) {
  return QString("QLabel { background: %1; color: white; padding: 6px; border-radius: 4px; font-weight: bold; }")
      .arg(color.name());
}
}  // namespace

SimulationView::SimulationView(QWidget* parent, std::size_t capacity)
    : QWidget(parent),
      time_(capacity),
      x_um_(capacity),
      y_um_(capacity),
      force_n_(capacity),
      power_w_(capacity),
      motion_plot_(makePlot(this,
                            tr("Tool vibration and resultant cutting force of the running simulation "
                               "(the last samples are kept). Wheel zooms, drag pans. A band is the least and greatest "
                               "value of the samples within each pixel column; zoom in for the samples."),
                            3)),
      power_plot_(makePlot(this,
                           tr("Spindle power P = v \u03a3 F_t against the machine's spindle power limit. Wheel "
                              "zooms, drag pans. A band is the least and greatest value within each pixel column."),
                           2)),
      spectrum_(new SpectrumPlot(this)),
      replot_timer_(new QTimer(this)) {
  motion_plot_->xAxis->setLabel(tr("Time t [s]"));
  // Short axis labels: the plots are short in the dock; the legends under them give the full names.
  motion_plot_->yAxis->setLabel(tr("x, y [\u00b5m]"));
  motion_plot_->yAxis2->setVisible(true);
  motion_plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  motion_plot_->yAxis2->setLabelColor(kForceColor);
  motion_plot_->yAxis2->setTickLabelColor(kForceColor);
  // A few ticks: the plots are ~100 px tall in the dock at 1080p.
  for (QCPAxis* axis : {motion_plot_->yAxis, motion_plot_->yAxis2, power_plot_->yAxis}) axis->ticker()->setTickCount(3);
  // The force first, so that the displacements are drawn over it.
  force_trace_ = std::make_unique<TraceGraph>(motion_plot_, motion_plot_->yAxis2, kForceColor, kForceBandAlpha);
  x_trace_ = std::make_unique<TraceGraph>(motion_plot_, motion_plot_->yAxis, kXColor);
  y_trace_ = std::make_unique<TraceGraph>(motion_plot_, motion_plot_->yAxis, kYColor);
  x_trace_->setName(tr("Displacement x [\u00b5m]"));
  y_trace_->setName(tr("Displacement y [\u00b5m]"));

  power_plot_->xAxis->setLabel(tr("Time t [s]"));
  power_plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  power_trace_ = std::make_unique<TraceGraph>(power_plot_, power_plot_->yAxis, kPowerColor);
  limit_graph_ = power_plot_->addGraph();
  limit_graph_->setName(tr("Spindle power limit"));
  limit_graph_->setPen(QPen(kLimitColor, 2.0, Qt::DashLine));
  // Each layout (a flush, a zoom, a pan, a resize) draws the traces for the range and width it shows.
  for (QCustomPlot* plot : {motion_plot_, power_plot_})
    connect(plot, &QCustomPlot::afterLayout, this, [this, plot] { drawTraces(plot); });

  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(kSpacing, kSpacing, kSpacing, kSpacing);
  grid->setSpacing(kSpacing);
  // Time plots stacked on the left, the spectrum and the indicators beside them at full height.
  grid->addWidget(motion_plot_, 0, 0);
  grid->addWidget(power_plot_, 1, 0);
  grid->addWidget(spectrum_, 0, 1, 2, 1);
  grid->addWidget(buildIndicatorPanel(), 0, 2, 2, 1);
  grid->setColumnStretch(0, 4);
  grid->setColumnStretch(1, 3);
  grid->setColumnStretch(2, 2);
  grid->setRowStretch(0, 1);
  grid->setRowStretch(1, 1);

  replot_timer_->setSingleShot(true);
  replot_timer_->setInterval(kReplotIntervalMs);
  connect(replot_timer_, &QTimer::timeout, this, &SimulationView::flushPlots);
  relabel();
  clear();
}

SimulationView::~SimulationView() = default;

void SimulationView::setUnits(DisplayUnits* units) {
  const auto apply = [this] {
    relabel();
    if (summary_ && !stale_) showSummaryValues(*summary_);
    flushPlots();
  };
  followUnits(this, units_, units, apply);
}

// The axis labels and legend names that carry a shop unit.
void SimulationView::relabel() {
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString force = u.symbol(Quantity::Force), power = u.symbol(Quantity::Power);
  motion_plot_->yAxis2->setLabel(tr("|F| [%1]").arg(force));
  force_trace_->setName(tr("Resultant force |F| [%1] (right axis)").arg(force));
  power_plot_->yAxis->setLabel(tr("P [%1]").arg(power));
  power_trace_->setName(tr("Spindle power P [%1]").arg(power));
  spectrum_->setAmplitudeUnit(force);
}

QWidget* SimulationView::buildIndicatorPanel() {
  auto* panel = new QWidget(this);
  auto* layout = new QVBoxLayout(panel);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(kSpacing);
  status_label_ = new QLabel(panel);
  verdict_label_ = new QLabel(panel);
  verdict_label_->setWordWrap(true);
  eta_gauge_ = new IndicatorGauge(QStringLiteral("\u03b7"),
                                  tr("\u03b7 = max|F_dynamic| / max|F_static| over the evaluated revolutions "
                                     "(Rubio et al. 2006, eq. 11)"),
                                  1.3, panel);
  eta_gauge_->setObjectName(QStringLiteral("etaGauge"));
  eta_gauge_->setWhatsThis(glossaryText(Term::Eta));
  chip_gauge_ = new IndicatorGauge(tr("Chip ratio h_dyn/h_st"),
                                   tr("Maximum dynamic over maximum static chip thickness (Rule 15)"), 1.25, panel);
  details_label_ = new QLabel(panel);
  details_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  details_label_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  move_button_ = new QPushButton(panel);
  move_button_->setObjectName(QStringLiteral("moveToSpeedButton"));
  connect(move_button_, &QPushButton::clicked, this, [this] {
    if (suggested_rpm_ > 0.0) emit moveToPointRequested(suggested_rpm_, suggested_depth_mm_);
  });
  suggestion_label_ = new QLabel(panel);
  suggestion_label_->setObjectName(QStringLiteral("suggestionNote"));
  suggestion_label_->setWordWrap(true);
  layout->addWidget(status_label_);
  layout->addWidget(verdict_label_);
  layout->addWidget(eta_gauge_);
  layout->addWidget(chip_gauge_);
  layout->addWidget(details_label_);
  layout->addWidget(move_button_);
  layout->addWidget(suggestion_label_);
  layout->addStretch(1);
  return panel;
}

void SimulationView::clear() {
  replot_timer_->stop();
  summary_.reset();
  stale_ = false;
  setPlotsGreyed(false);
  for (RingBuffer<double>* b : {&time_, &x_um_, &y_um_, &force_n_, &power_w_}) b->clear();
  running_ = false;
  summary_shown_ = false;
  chatter_shown_ = false;
  suggested_rpm_ = 0.0;
  eta_gauge_->clear();
  chip_gauge_->clear();
  status_label_->setText(tr("No simulation yet: pick an operating point."));
  verdict_label_->setText(tr("Verdict: \u2013"));
  verdict_label_->setStyleSheet(verdictStyle(palette().color(QPalette::Mid)));
  details_label_->clear();
  move_button_->setText(tr("Move to suggested speed"));
  move_button_->setEnabled(false);
  move_button_->setToolTip(tr("Shown when chatter is detected: the Smith-Tlusty speed N = 60 f_c / (n_t k)."));
  suggestion_label_->clear();
  spectrum_->clear();
  spectrum_->setToothPassingHz(tooth_passing_hz_);
  flushPlots();
}

void SimulationView::beginRun(double spindle_power_limit_w, int teeth, double tooth_passing_hz) {
  power_limit_w_ = std::isfinite(spindle_power_limit_w) && spindle_power_limit_w > 0.0 ? spindle_power_limit_w : 0.0;
  teeth_ = teeth;
  tooth_passing_hz_ = tooth_passing_hz;
  for (TraceGraph* t : {x_trace_.get(), y_trace_.get(), force_trace_.get(), power_trace_.get()})
    t->setShortestBucket(tooth_passing_hz > 0.0 ? 1.0 / tooth_passing_hz : 0.0);
  clear();
  running_ = true;
  spectrum_clock_.start();
  status_label_->setText(tr("Simulating\u2026"));
  verdict_label_->setText(tr("Verdict: pending (the indicators use the last revolutions)"));
}

void SimulationView::appendChunk(const mx::gui::SimulationChunkData& chunk) {
  const qsizetype n =
      std::min({chunk.time_s.size(), chunk.x_m.size(), chunk.y_m.size(), chunk.force_n.size(), chunk.power_w.size()});
  // Only the last capacity() samples of a chunk can survive.
  const qsizetype first = std::max<qsizetype>(0, n - static_cast<qsizetype>(capacity()));
  for (qsizetype i = first; i < n; ++i) {
    time_.push(chunk.time_s[i]);
    x_um_.push(chunk.x_m[i] * 1e6);
    y_um_.push(chunk.y_m[i] * 1e6);
    force_n_.push(chunk.force_n[i]);
    power_w_.push(chunk.power_w[i]);
  }
  if (chunk.revolutions > 0 && !summary_shown_)
    status_label_->setText(tr("Simulating\u2026 revolution %1 of %2 (%3 %)")
                               .arg(chunk.revolution)
                               .arg(chunk.revolutions)
                               .arg(100 * chunk.revolution / chunk.revolutions));
  scheduleReplot();
}

void SimulationView::setSummary(const mx::gui::SimulationSummary& s) {
  running_ = false;
  summary_shown_ = true;
  summary_ = s;
  tooth_passing_hz_ = s.tooth_passing_hz;
  eta_gauge_->setThreshold(s.eta_threshold);
  eta_gauge_->setValue(s.eta);
  chip_gauge_->setThreshold(s.chip_ratio_threshold);
  chip_gauge_->setValue(s.chip_ratio);
  chatter_shown_ = s.chatter;

  QString verdict;
  if (s.chatter) {
    QStringList by;
    if (s.chatter_by_eta) by << tr("\u03b7 \u2265 %1").arg(s.eta_threshold);
    if (s.chatter_by_chip_ratio) by << tr("chip ratio \u2265 %1").arg(s.chip_ratio_threshold);
    verdict = s.chatter_frequency_hz
                  ? tr("CHATTER at f_c = %1 Hz (%2)").arg(*s.chatter_frequency_hz, 0, 'f', 1).arg(by.join(", "))
                  : tr("CHATTER (%1)").arg(by.join(", "));
  } else {
    verdict = tr("STABLE: no chatter (\u03b7 < %1, chip ratio < %2)").arg(s.eta_threshold).arg(s.chip_ratio_threshold);
  }
  if (s.diverged) verdict += tr("; vibration diverged after %1 revolutions").arg(s.simulated_revolutions);
  verdict_label_->setText(verdict);
  verdict_label_->setStyleSheet(verdictStyle(s.chatter ? IndicatorGauge::alarmColor() : IndicatorGauge::okColor()));
  status_label_->setText(tr("Finished: %1 revolutions at %2 rpm; indicators over the last %3")
                             .arg(s.simulated_revolutions)
                             .arg(s.spindle_rpm, 0, 'f', 0)
                             .arg(s.evaluated_revolutions));

  suggested_rpm_ = s.suggested_rpm.value_or(0.0);
  suggested_depth_mm_ = s.suggested_depth_mm.value_or(std::numeric_limits<double>::quiet_NaN());
  move_button_->setEnabled(suggested_rpm_ > 0.0);
  suggestion_label_->setText(s.suggestion_note);
  showSummaryValues(s);
  if (suggested_rpm_ > 0.0 && s.suggested_depth_mm) {
    move_button_->setToolTip(s.suggestion_note);
  } else if (suggested_rpm_ > 0.0) {
    move_button_->setText(tr("Move to %1 rpm").arg(suggested_rpm_, 0, 'f', 0));
    move_button_->setToolTip(
        s.suggested_k > 0 ? tr("Smith-Tlusty: tooth-passing frequency = f_c / %1, i.e. N = 60 f_c / (%2 \u00d7 %1) rpm")
                                .arg(s.suggested_k)
                                .arg(s.teeth)
                          : s.suggestion_note);
  } else {
    move_button_->setText(s.chatter ? tr("No chatter-free speed in range") : tr("Move to suggested speed"));
  }

  spectrum_->setToothPassingHz(s.tooth_passing_hz);
  spectrum_->setChatterFrequency(s.chatter_frequency_hz);
  scheduleReplot();
}

// What of the summary is in shop units: the details, the suggested depth and the spectrum.
void SimulationView::showSummaryValues(const mx::gui::SimulationSummary& s) {
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString power_limit = s.spindle_power_limit_w > 0.0
                                  ? tr(" of %1 limit%2")
                                        .arg(u.format(Quantity::Power, s.spindle_power_limit_w))
                                        .arg(s.power_limit_exceeded ? tr(": EXCEEDED") : QString())
                                  : QString();
  details_label_->setText(
      tr("Tooth-passing frequency f_tp: %1 Hz\nChatter frequency f_c: %2\nA_chatter: %3 %8    A_toothpass: %4 %8\n"
         "Peak force: %5\nPeak power: %6%7")
          .arg(s.tooth_passing_hz, 0, 'f', 1)
          .arg(s.chatter_frequency_hz ? tr("%1 Hz").arg(*s.chatter_frequency_hz, 0, 'f', 1) : tr("\u2013 (no chatter)"))
          .arg(u.fromBase(Quantity::Force, s.a_chatter_n), 0, 'g', 4)
          .arg(u.fromBase(Quantity::Force, s.a_toothpass_n), 0, 'g', 4)
          .arg(u.format(Quantity::Force, s.peak_force_n))
          .arg(u.format(Quantity::Power, s.peak_power_w))
          .arg(power_limit)
          .arg(u.symbol(Quantity::Force)));
  if (suggested_rpm_ > 0.0 && s.suggested_depth_mm)
    move_button_->setText(tr("Move to %1 rpm, b = %2")
                              .arg(suggested_rpm_, 0, 'f', 0)
                              .arg(u.format(Quantity::Length, *s.suggested_depth_mm)));
  QVector<double> amplitude = s.spectrum_n;
  for (double& a : amplitude) a = u.fromBase(Quantity::Force, a);
  spectrum_->setSpectrum({s.spectrum_hz, amplitude}, tr("last %1 revolutions").arg(s.evaluated_revolutions));
}

void SimulationView::setStatus(const QString& message) {
  running_ = false;
  status_label_->setText(message);
}

void SimulationView::setStale(const QString& reason) {
  stale_ = true;
  running_ = false;
  setPlotsGreyed(true);
  status_label_->setText(tr("Stale: %1").arg(reason));
  verdict_label_->setText(tr("Verdict: \u2013 (stale)"));
  verdict_label_->setStyleSheet(verdictStyle(palette().color(QPalette::Mid)));
  suggested_rpm_ = 0.0;
  move_button_->setText(tr("Move to suggested speed"));
  move_button_->setEnabled(false);
  suggestion_label_->clear();
}

QString SimulationView::suggestionNote() const {
  return suggestion_label_->text();
}

QString SimulationView::statusText() const {
  return status_label_->text();
}

void SimulationView::setPlotsGreyed(bool greyed) {
  for (QWidget* plot :
       {static_cast<QWidget*>(motion_plot_), static_cast<QWidget*>(power_plot_), static_cast<QWidget*>(spectrum_)}) {
    if (!greyed) {
      plot->setGraphicsEffect(nullptr);
      continue;
    }
    auto* effect = new QGraphicsOpacityEffect(plot);
    effect->setOpacity(0.35);
    plot->setGraphicsEffect(effect);
  }
}

int SimulationView::spectrumPointCount() const {
  return spectrum_->pointCount();
}
QString SimulationView::verdictText() const {
  return verdict_label_->text();
}
QString SimulationView::suggestedSpeedText() const {
  return suggested_rpm_ > 0.0 ? move_button_->text() : QString();
}
bool SimulationView::replotPending() const {
  return replot_timer_->isActive();
}

void SimulationView::scheduleReplot() {
  if (!replot_timer_->isActive()) replot_timer_->start();  // coalesces the chunks of ~33 ms
}

void SimulationView::flushPlots() {
  ++flush_count_;
  double lo = 0.0, hi = 0.0, f_lo = 0.0, f_hi = 0.0, p_lo = 0.0, p_hi = 0.0, t_lo = 0.0, t_hi = 0.0;
  plot_t_ = plotValues(time_, t_lo, t_hi);
  plot_x_ = plotValues(x_um_, lo, hi);
  plot_y_ = plotValues(y_um_, lo, hi);
  const ShopUnits& u = DisplayUnits::of(units_);
  const double force = u.fromBase(Quantity::Force, 1.0), power = u.fromBase(Quantity::Power, 1.0);
  plot_force_ = plotValues(force_n_, f_lo, f_hi, force);
  plot_power_ = plotValues(power_w_, p_lo, p_hi, power);
  const double t0 = time_.empty() ? 0.0 : time_.front();
  const double t1 = time_.empty() ? 1.0 : std::max(time_.back(), t0 + 1e-6);
  const double amplitude = std::max({std::abs(lo), std::abs(hi), 1e-3});
  motion_plot_->xAxis->setRange(t0, t1);
  motion_plot_->yAxis->setRange(-1.1 * amplitude, 1.1 * amplitude);
  motion_plot_->yAxis2->setRange(0.0, std::max(f_hi, force) * 1.1);
  power_plot_->xAxis->setRange(t0, t1);
  p_hi = std::max(p_hi, power);  // at least 1 W
  updatePowerLimit();
  // Keep the trace readable: the limit sets the range only when within 4x the peak.
  const double limit = power * power_limit_w_;
  const bool limit_in_range = limit > 0.0 && limit <= 4.0 * p_hi;
  power_plot_->yAxis->setRange(0.0, 1.12 * (limit_in_range ? std::max(p_hi, limit) : p_hi));
  if (running_ && spectrum_clock_.isValid() && spectrum_clock_.elapsed() >= kLiveSpectrumIntervalMs) {
    updateLiveSpectrum();
    spectrum_clock_.restart();
  }
  motion_plot_->replot(QCustomPlot::rpQueuedReplot);
  power_plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SimulationView::drawTraces(QCustomPlot* plot) {
  if (plot == power_plot_) return power_trace_->show(plot_t_, plot_power_);
  force_trace_->show(plot_t_, plot_force_);
  x_trace_->show(plot_t_, plot_x_);
  y_trace_->show(plot_t_, plot_y_);
}

const TraceGraph& SimulationView::trace(Trace trace) const {
  switch (trace) {
    case Trace::X:
      return *x_trace_;
    case Trace::Y:
      return *y_trace_;
    case Trace::Force:
      return *force_trace_;
    case Trace::Power:
      break;
  }
  return *power_trace_;
}

bool SimulationView::envelopeShown(Trace t) const {
  return trace(t).envelopeShown();
}
int SimulationView::drawnPointCount(Trace t) const {
  return trace(t).drawnPoints();
}
std::pair<double, double> SimulationView::drawnValueRange(Trace t) const {
  return trace(t).drawnRange();
}
int SimulationView::plotColumns(Trace t) const {
  return trace(t).columns();
}
int SimulationView::envelopeBuckets(Trace t) const {
  return trace(t).buckets();
}
QColor SimulationView::traceColor(Trace t) const {
  return t == Trace::X ? kXColor : t == Trace::Y ? kYColor : t == Trace::Force ? kForceColor : kPowerColor;
}
QColor SimulationView::axisLabelColor(Trace t) const {
  const QCPAxis* axis = t == Trace::Power   ? power_plot_->yAxis
                        : t == Trace::Force ? motion_plot_->yAxis2
                                            : motion_plot_->yAxis;
  return axis->labelColor();
}

void SimulationView::setTimeRange(double t0, double t1) {
  for (QCustomPlot* plot : {motion_plot_, power_plot_}) {
    plot->xAxis->setRange(t0, t1);
    plot->replot(QCustomPlot::rpQueuedReplot);
  }
}

void SimulationView::updatePowerLimit() {
  if (power_limit_w_ <= 0.0 || time_.empty()) {
    limit_graph_->data()->clear();
    if (power_limit_w_ <= 0.0) limit_graph_->removeFromLegend();
    return;
  }
  limit_graph_->addToLegend();
  double p_hi = 1.0;
  for (std::size_t i = 0; i < power_w_.size(); ++i) p_hi = std::max(p_hi, power_w_[i]);
  const bool above = power_limit_w_ > 4.0 * p_hi;
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString limit = u.format(Quantity::Power, power_limit_w_);
  limit_graph_->setName(above ? tr("Spindle power limit %1 (above the range)").arg(limit)
                              : tr("Spindle power limit %1").arg(limit));
  const double shown = u.fromBase(Quantity::Power, power_limit_w_);
  limit_graph_->setData({time_.front(), time_.back()}, {shown, shown}, true);
}

void SimulationView::updateLiveSpectrum() {
  const std::size_t n = std::min(force_n_.size(), kLiveSpectrumSamples);
  if (n < 64) return;
  std::vector<double> signal(n);
  const std::size_t first = force_n_.size() - n;
  const double force = DisplayUnits::of(units_).fromBase(Quantity::Force, 1.0);  // the spectrum is linear
  for (std::size_t i = 0; i < n; ++i) signal[i] = force * force_n_[first + i];
  const double duration = time_.back() - time_[first];
  if (!(duration > 0.0)) return;
  const double rate = static_cast<double>(n - 1) / duration;
  const double revolutions = teeth_ > 0 ? duration * tooth_passing_hz_ / teeth_ : 0.0;
  spectrum_->setSpectrum(SpectrumPlot::computeSpectrum(signal, rate, tooth_passing_hz_),
                         tr("live, last %1 revolutions").arg(revolutions, 0, 'f', 1));
}

}  // namespace mx::widgets
