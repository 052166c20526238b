#include "surface_finish_panel.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "indicator_gauge.h"
#include "monitoring_panel.h"

namespace mx::widgets {

namespace {
constexpr int kSpacing = 8;
const QString kMissing = QStringLiteral("\u2013");
const QColor kActualColor(31, 119, 180);
const QColor kDynamicColor(255, 127, 14);
const QColor kReferenceColor(214, 39, 40);
const QColor kFeedColor(44, 160, 44);
const QColor kSpeedColor(148, 103, 189);
const QColor kBaselineColor(90, 90, 90);
const char* const kBaselineGraphs[] = {"ra_baseline", "force_baseline", "feed_baseline", "speed_baseline"};

struct SummarySpec {
  const char* key;
  const char* label;  // %1: the shop unit of `quantity`
  const char* tip;
  std::optional<Quantity> quantity = std::nullopt;
};

constexpr SummarySpec kSummary[] = {
    {"ra_desired_um", "Ra desired [\u00b5m]", "Desired arithmetic mean roughness Ra_d of the run"},
    {"ra_produced_um", "Ra produced [\u00b5m]", "Roughness Ra at the end of the run, with the machine-tool dynamics"},
    {"fd_n", "F_d [%1]", "Reference cutting force F_d that yields Ra_d (from the inverted roughness model)",
     Quantity::Force},
    {"f_final_n", "F [%1]", "Cutting force at the end of the run", Quantity::Force},
    {"feed_final_mm_min", "f_a [%1]", "Feed at the end of the run, as set by the force controller", Quantity::Feed},
    {"speed_final_rpm", "n_a [rpm]", "Spindle speed at the end of the run"},
    {"ra_baseline_um", "Ra no SDNRP [\u00b5m]",
     "Roughness Ra at the end of the run without SDNRP (feed and speed held at the initial ones), with the "
     "machine-tool dynamics"},
    {"f_baseline_n", "F no SDNRP [%1]", "Cutting force at the end of the run without SDNRP", Quantity::Force},
};
constexpr std::size_t kRunSummaryCount = 6;  // the entries of the run with SDNRP

QString format(double v) {
  return MonitoringPanel::formatNumber(v);
}

struct SpinSpec {
  double lo, hi;
  int decimals;
  double step, value;
};

// "<label>:" and a spin box sharing the tooltip, added to `row`.
QDoubleSpinBox* addSpin(QHBoxLayout* row, const QString& label, const char* name, SpinSpec spec, const QString& tip) {
  QWidget* parent = row->parentWidget();
  auto* text = new QLabel(label, parent);
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(QLatin1String(name));
  spin->setRange(spec.lo, spec.hi);
  spin->setDecimals(spec.decimals);
  spin->setSingleStep(spec.step);
  spin->setValue(spec.value);
  text->setToolTip(tip);
  spin->setToolTip(tip);
  text->setBuddy(spin);
  row->addWidget(text);
  row->addWidget(spin);
  return spin;
}
}  // namespace

void SurfaceFinishPanel::Range::add(double v) {
  if (!std::isfinite(v)) return;
  lo = any ? std::min(lo, v) : v;
  hi = any ? std::max(hi, v) : v;
  any = true;
}

SurfaceFinishPanel::SurfaceFinishPanel(QWidget* parent) : QWidget(parent), debounce_(new QTimer(this)) {
  setToolTip(
      tr("Surface-finish control (Cus & Zuperl SDNRP): the force controller adapts the feed so that the "
         "cutting force follows F_d, the force that yields the desired roughness Ra_d."));
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(kSpacing, kSpacing, kSpacing, kSpacing);
  outer->setSpacing(kSpacing);
  outer->addWidget(buildControls());

  auto* grid = new QGridLayout;
  grid->setSpacing(kSpacing);
  QCustomPlot* ra = makePlot(tr("Roughness Ra [\u00b5m]"),
                             tr("Surface roughness Ra: the model value and the value with the machine-tool dynamics "
                                "(disturbance); dashed: the desired Ra_d."));
  QCustomPlot* force =
      makePlot(QString(), tr("Cutting force F, and F with its dynamic (disturbance) component; dashed: the "
                             "reference F_d that yields Ra_d."));
  QCustomPlot* feed = makePlot(QString(), tr("Feed f_a commanded by the force controller."));
  QCustomPlot* speed = makePlot(tr("Spindle speed n_a [rpm]"), tr("Spindle speed n_a."));
  auto add = [this](QCustomPlot* plot, const char* key, const QString& name, const QPen& pen) {
    QCPGraph* g = plot->addGraph();
    g->setName(name);
    g->setPen(pen);
    graphs_.insert(QString::fromLatin1(key), g);
    return g;
  };
  add(ra, "ra", tr("Ra, SDNRP [\u00b5m]"), QPen(kActualColor, 2.0));
  add(ra, "ra_dynamic", tr("Ra with machine-tool dynamics, SDNRP [\u00b5m]"), QPen(kDynamicColor, 1.0));
  add(ra, "ra_desired", tr("Desired Ra_d [\u00b5m]"), QPen(kReferenceColor, 2.0, Qt::DashLine));
  add(force, "force", QString(), QPen(kActualColor, 2.0));
  add(force, "force_dynamic", QString(), QPen(kDynamicColor, 1.0));
  add(force, "fd", tr("Reference F_d"), QPen(kReferenceColor, 2.0, Qt::DashLine));
  add(feed, "feed", QString(), QPen(kFeedColor, 2.0));
  add(speed, "speed", tr("Spindle speed n_a, SDNRP [rpm]"), QPen(kSpeedColor, 2.0));
  // The run without SDNRP (Figs 12 and 14 of Cus & Zuperl): what the machine feels, dashed.
  const QPen baseline(kBaselineColor, 1.0, Qt::DashLine);
  add(ra, "ra_baseline", tr("Ra with machine-tool dynamics, no SDNRP (constant feed) [\u00b5m]"), baseline);
  add(force, "force_baseline", QString(), baseline);
  add(feed, "feed_baseline", QString(), baseline);
  add(speed, "speed_baseline", tr("Spindle speed n_a, no SDNRP (constant) [rpm]"), baseline);
  grid->addWidget(ra, 0, 0);
  grid->addWidget(force, 0, 1);
  grid->addWidget(feed, 1, 0);
  grid->addWidget(speed, 1, 1);
  outer->addLayout(grid, 1);
  outer->addWidget(buildSummary());

  debounce_->setSingleShot(true);
  debounce_->setInterval(kDebounceMs);
  connect(debounce_, &QTimer::timeout, this, &SurfaceFinishPanel::runRequested);
  relabel();
  clear();
}

void SurfaceFinishPanel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &SurfaceFinishPanel::reshow);
}

// The labels of the force and feed, in shop units.
void SurfaceFinishPanel::relabel() {
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString force = u.symbol(Quantity::Force), feed = u.symbol(Quantity::Feed);
  plots_[1]->yAxis->setLabel(tr("Cutting force F [%1]").arg(force));
  plots_[2]->yAxis->setLabel(tr("Feed f_a [%1]").arg(feed));
  graphs_["force"]->setName(tr("F, SDNRP [%1]").arg(force));
  graphs_["force_dynamic"]->setName(tr("F with dynamic component, SDNRP [%1]").arg(force));
  graphs_["feed"]->setName(tr("Feed f_a, SDNRP [%1]").arg(feed));
  graphs_["force_baseline"]->setName(tr("F with dynamic component, no SDNRP (constant feed) [%1]").arg(force));
  graphs_["feed_baseline"]->setName(tr("Feed f_a, no SDNRP (constant) [%1]").arg(feed));
  for (const SummarySpec& spec : kSummary)
    summary_names_[QLatin1String(spec.key)]->setText(
        (spec.quantity ? tr(spec.label).arg(u.symbol(*spec.quantity)) : tr(spec.label)) + ":");
}

// The run shown again after a change of units: the labels, the samples and the summary.
void SurfaceFinishPanel::reshow() {
  relabel();
  replayShown();
}

// Clears the plots and shows the kept run and its baseline (if any) again, with the same status text.
void SurfaceFinishPanel::replayShown() {
  const QVector<SurfaceFinishSample> samples = samples_;
  const std::optional<SurfaceFinishSummary> summary = shown_summary_;
  const QVector<SurfaceFinishSample> baseline = baseline_;
  const std::optional<SurfaceFinishSummary> baseline_summary = baseline_summary_;
  const QString status = status_label_->text();
  const bool busy = busy_;
  busy_ = true;  // clear() keeps the status text while busy
  clear();
  busy_ = busy;
  appendSamples(samples);
  if (summary) setSummary(*summary);
  if (baseline_summary) setBaseline(baseline, *baseline_summary);
  status_label_->setText(status);
}

QCustomPlot* SurfaceFinishPanel::makePlot(const QString& y_label, const QString& tooltip) {
  auto* plot = new QCustomPlot(this);
  plot->setObjectName(QStringLiteral("surfaceFinishPlot%1").arg(plots_.size()));
  plot->setMinimumSize(320, 180);
  plot->setToolTip(tooltip + tr(" Wheel zooms, drag pans."));
  plot->xAxis->setLabel(tr("Time t [s]"));
  plot->yAxis->setLabel(y_label);
  // The legend above the axes, two entries a line, so that it hides no curve: a strip of the legend and
  // a spacer (a legend alone would cap the width of the column at its own).
  plot->axisRect()->insetLayout()->take(plot->legend);
  plot->axisRect()->insetLayout()->simplify();
  plot->plotLayout()->insertRow(0);
  auto* strip = new QCPLayoutGrid;
  plot->plotLayout()->addElement(0, 0, strip);
  plot->plotLayout()->setRowStretchFactor(0, 0.001);
  strip->addElement(0, 0, plot->legend);
  strip->addElement(0, 1, new QCPLayoutElement(plot));
  plot->legend->setVisible(true);
  plot->legend->setFont(QFont(font().family(), 9));
  plot->legend->setBorderPen(Qt::NoPen);
  plot->legend->setBrush(Qt::NoBrush);
  plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  plot->legend->setWrap(2);
  plot->legend->setColumnSpacing(24);
  plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plots_.push_back(plot);
  return plot;
}

QWidget* SurfaceFinishPanel::buildControls() {
  auto* box = new QWidget(this);
  auto* row = new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  row->setSpacing(kSpacing);

  ra_spin_ = addSpin(row, tr("Desired Ra [\u00b5m]:"), "surfaceFinishRa", {kMinRaUm, kMaxRaUm, 2, 0.05, kDefaultRaUm},
                     tr("Desired arithmetic mean roughness Ra_d, %1 to %2 \u00b5m; the reference force F_d "
                        "follows from the inverted roughness model.")
                         .arg(kMinRaUm)
                         .arg(kMaxRaUm));
  disturbance_box_ = new QCheckBox(tr("Machine-tool disturbance"), box);
  disturbance_box_->setObjectName(QStringLiteral("surfaceFinishDisturbance"));
  disturbance_box_->setToolTip(
      tr("Adds the dynamic component of the machine tool (vibration) to the cutting force "
         "and the roughness; the controller has to reject it."));
  row->addWidget(disturbance_box_);
  compare_box_ = new QCheckBox(tr("Compare with constant feed (no SDNRP)"), box);
  compare_box_->setObjectName(QStringLiteral("surfaceFinishCompare"));
  compare_box_->setChecked(true);
  compare_box_->setToolTip(
      tr("Also runs the same cut without the SDNRP loop (feed and speed held at the initial cutting "
         "conditions, same disturbance) and draws it dashed: the paper's force and roughness \"without "
         "application of SDNRP\"."));
  row->addWidget(compare_box_);
  duration_spin_ = addSpin(row, tr("Duration [s]:"), "surfaceFinishDuration",
                           {kMinDurationS, kMaxDurationS, 1, 1.0, kDefaultDurationS},
                           tr("Simulated machining time, %1 to %2 s.").arg(kMinDurationS).arg(kMaxDurationS));

  run_button_ = new QPushButton(tr("Run"), box);
  run_button_->setObjectName(QStringLiteral("surfaceFinishRun"));
  run_button_->setToolTip(
      tr("Simulate the SDNRP surface-finish loop with these settings (also runs 300 ms after "
         "a change)."));
  status_label_ = new QLabel(box);
  status_label_->setObjectName(QStringLiteral("surfaceFinishStatus"));

  row->addWidget(run_button_);
  row->addWidget(status_label_, 1);

  connect(ra_spin_, &QDoubleSpinBox::valueChanged, this, [this] {
    if (!summary_shown_) setReferences(desiredRaUm(), std::nullopt);
    userChanged();
  });
  connect(disturbance_box_, &QCheckBox::toggled, this, &SurfaceFinishPanel::userChanged);
  connect(compare_box_, &QCheckBox::toggled, this, &SurfaceFinishPanel::userChanged);
  connect(duration_spin_, &QDoubleSpinBox::valueChanged, this, [this] {
    updateRanges();
    replotAll();
    userChanged();
  });
  connect(run_button_, &QPushButton::clicked, this, [this] {
    debounce_->stop();  // a pending debounced request is this run
    emit runRequested();
  });
  return box;
}

QWidget* SurfaceFinishPanel::buildSummary() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* grid = new QGridLayout;
  grid->setHorizontalSpacing(2 * kSpacing);
  int column = 0;
  for (const SummarySpec& s : kSummary) {
    auto* name = new QLabel(box);
    summary_names_.insert(QString::fromLatin1(s.key), name);
    auto* value = new QLabel(box);
    value->setObjectName(QStringLiteral("surfaceFinish_%1").arg(QLatin1String(s.key)));
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    value->setStyleSheet(QStringLiteral("QLabel { font-weight: bold; }"));
    name->setToolTip(tr(s.tip));
    value->setToolTip(tr(s.tip));
    grid->addWidget(name, 0, column, Qt::AlignRight);
    grid->addWidget(value, 0, column + 1, Qt::AlignLeft);
    column += 2;
    summary_.insert(QString::fromLatin1(s.key), value);
  }
  grid->setColumnStretch(column, 1);
  layout->addLayout(grid);
  warning_label_ = new QLabel(box);
  warning_label_->setObjectName(QStringLiteral("surfaceFinishWarning"));
  warning_label_->setWordWrap(true);
  warning_label_->setStyleSheet(
      QString("QLabel { color: %1; font-weight: bold; }").arg(IndicatorGauge::alarmColor().name()));
  warning_label_->setToolTip(
      tr("The feed reached its limit before the force reached F_d: the desired roughness "
         "cannot be produced with these cutting conditions."));
  layout->addWidget(warning_label_);
  return box;
}

double SurfaceFinishPanel::desiredRaUm() const {
  return ra_spin_->value();
}

void SurfaceFinishPanel::setDesiredRaUm(double ra) {
  if (std::isnan(ra)) return;
  programmatic_ = true;
  ra_spin_->setValue(std::clamp(ra, kMinRaUm, kMaxRaUm));
  programmatic_ = false;
}

bool SurfaceFinishPanel::disturbanceOn() const {
  return disturbance_box_->isChecked();
}

void SurfaceFinishPanel::setDisturbanceOn(bool on) {
  programmatic_ = true;
  disturbance_box_->setChecked(on);
  programmatic_ = false;
}

double SurfaceFinishPanel::durationS() const {
  return duration_spin_->value();
}

void SurfaceFinishPanel::setDurationS(double s) {
  if (std::isnan(s)) return;
  programmatic_ = true;
  duration_spin_->setValue(std::clamp(s, kMinDurationS, kMaxDurationS));
  programmatic_ = false;
}

bool SurfaceFinishPanel::compareOn() const {
  return compare_box_->isChecked();
}

void SurfaceFinishPanel::setCompareOn(bool on) {
  programmatic_ = true;
  compare_box_->setChecked(on);
  programmatic_ = false;
}

void SurfaceFinishPanel::userChanged() {
  if (!programmatic_) debounce_->start();  // restarts: one request after the last change
}

void SurfaceFinishPanel::clear() {
  samples_.clear();
  shown_summary_.reset();
  baseline_.clear();
  baseline_summary_.reset();
  for (const char* key : {"ra", "ra_dynamic", "force", "force_dynamic", "feed", "speed"})
    graphs_[QLatin1String(key)]->data()->clear();
  for (const char* key : kBaselineGraphs) graphs_[QLatin1String(key)]->data()->clear();
  showBaselineLegend(false);
  for (Range& r : ranges_) r = Range{};
  sample_count_ = 0;
  last_t_ = 0.0;
  summary_shown_ = false;
  fd_shown_ = false;
  for (QLabel* label : std::as_const(summary_)) label->setText(kMissing);
  warning_label_->clear();
  warning_label_->hide();
  setReferences(desiredRaUm(), std::nullopt);
  if (!busy_) status_label_->setText(tr("No run yet: set Ra and press Run."));
}

void SurfaceFinishPanel::appendSamples(const QVector<SurfaceFinishSample>& samples) {
  if (samples.isEmpty()) return;
  samples_ += samples;
  const ShopUnits& u = DisplayUnits::of(units_);
  QCPGraph* g[] = {graphs_["ra"],   graphs_["ra_dynamic"], graphs_["force"], graphs_["force_dynamic"],
                   graphs_["feed"], graphs_["speed"]};
  for (const SurfaceFinishSample& s : samples) {
    if (!std::isfinite(s.t_s)) continue;
    const double v[] = {s.ra_um,
                        s.ra_dynamic_um,
                        u.fromBase(Quantity::Force, s.force_n),
                        u.fromBase(Quantity::Force, s.force_dynamic_n),
                        u.fromBase(Quantity::Feed, s.feed_mm_min),
                        s.speed_rpm};
    constexpr int kPlotOf[] = {0, 0, 1, 1, 2, 3};
    for (int i = 0; i < 6; ++i) {
      if (!std::isfinite(v[i])) continue;
      g[i]->addData(s.t_s, v[i]);
      ranges_[kPlotOf[i]].add(v[i]);
    }
    last_t_ = std::max(last_t_, s.t_s);
    ++sample_count_;
  }
  if (!summary_shown_ && busy_)
    status_label_->setText(tr("SDNRP loop running... t = %1 of %2 s").arg(last_t_, 0, 'f', 1).arg(durationS()));
  updateRanges();
  replotAll();
}

void SurfaceFinishPanel::setSummary(const SurfaceFinishSummary& s) {
  summary_shown_ = true;
  shown_summary_ = s;
  const ShopUnits& u = DisplayUnits::of(units_);
  const double values[kRunSummaryCount] = {s.ra_desired_um,
                                           s.ra_produced_um,
                                           u.fromBase(Quantity::Force, s.fd_n),
                                           u.fromBase(Quantity::Force, s.f_final_n),
                                           u.fromBase(Quantity::Feed, s.feed_final_mm_min),
                                           s.speed_final_rpm};  // kSummary order
  for (std::size_t i = 0; i < kRunSummaryCount; ++i)
    summary_[QLatin1String(kSummary[i].key)]->setText(format(values[i]));
  setReferences(std::isfinite(s.ra_desired_um) ? s.ra_desired_um : desiredRaUm(), s.fd_n);
  warning_label_->setVisible(s.feed_saturated);
  warning_label_->setText(s.feed_saturated ? tr("F_d not reachable within the feed limits: the feed saturated at "
                                                "f_a = %1 with F = %2 against F_d = %3.")
                                                 .arg(format(values[4]) + " " + u.symbol(Quantity::Feed),
                                                      format(values[3]) + " " + u.symbol(Quantity::Force),
                                                      format(values[2]) + " " + u.symbol(Quantity::Force))
                                           : QString());
  finishedStatus();
}

void SurfaceFinishPanel::finishedStatus() {
  if (!shown_summary_) return;
  const SurfaceFinishSummary& s = *shown_summary_;
  QString text = tr("Finished: Ra %1 \u00b5m produced for %2 \u00b5m desired")
                     .arg(format(s.ra_produced_um), format(s.ra_desired_um));
  if (baseline_summary_)
    text += tr("; without SDNRP (constant feed) %1 \u00b5m").arg(format(baseline_summary_->ra_produced_um));
  status_label_->setText(text + ".");
}

void SurfaceFinishPanel::setBaseline(const QVector<SurfaceFinishSample>& samples, const SurfaceFinishSummary& summary) {
  clearBaseline();
  baseline_ = samples;
  baseline_summary_ = summary;
  const ShopUnits& u = DisplayUnits::of(units_);
  QCPGraph* g[] = {graphs_["ra_baseline"], graphs_["force_baseline"], graphs_["feed_baseline"],
                   graphs_["speed_baseline"]};
  for (const SurfaceFinishSample& s : samples) {
    if (!std::isfinite(s.t_s)) continue;
    // What the machine feels: F and Ra with the dynamic component (Figs 12 and 14).
    const double v[] = {s.ra_dynamic_um, u.fromBase(Quantity::Force, s.force_dynamic_n),
                        u.fromBase(Quantity::Feed, s.feed_mm_min), s.speed_rpm};
    for (int i = 0; i < 4; ++i) {
      if (!std::isfinite(v[i])) continue;
      g[i]->addData(s.t_s, v[i]);
      ranges_[i].add(v[i]);
    }
    last_t_ = std::max(last_t_, s.t_s);
  }
  summary_["ra_baseline_um"]->setText(format(summary.ra_produced_um));
  summary_["f_baseline_n"]->setText(format(u.fromBase(Quantity::Force, summary.f_final_n)));
  showBaselineLegend(true);
  finishedStatus();
  updateRanges();
  replotAll();
}

// The ranges are rebuilt from the run with SDNRP alone.
void SurfaceFinishPanel::clearBaseline() {
  if (!baseline_summary_ && baseline_.isEmpty()) return;
  baseline_.clear();
  baseline_summary_.reset();
  for (const char* key : kBaselineGraphs) graphs_[QLatin1String(key)]->data()->clear();
  for (const char* key : {"ra_baseline_um", "f_baseline_n"}) summary_[QLatin1String(key)]->setText(kMissing);
  showBaselineLegend(false);
  replayShown();
  finishedStatus();
}

void SurfaceFinishPanel::showBaselineLegend(bool shown) {
  for (const char* key : kBaselineGraphs) {
    QCPGraph* g = graphs_[QLatin1String(key)];
    if (shown)
      g->addToLegend();
    else
      g->removeFromLegend();
  }
}

void SurfaceFinishPanel::setBusy(bool busy) {
  busy_ = busy;
  run_button_->setEnabled(!busy);
  if (busy)
    status_label_->setText(tr("SDNRP loop running..."));
  else if (!summary_shown_ && status_label_->text().startsWith(tr("SDNRP loop running")))
    status_label_->setText(sample_count_ > 0 ? tr("Stopped.") : tr("No run yet: set Ra and press Run."));
}

void SurfaceFinishPanel::setReferences(double ra_d, std::optional<double> fd) {
  ra_reference_ = ra_d;
  fd_shown_ = fd && std::isfinite(*fd);
  fd_reference_ = fd_shown_ ? *fd : 0.0;
  updateRanges();
  replotAll();
}

void SurfaceFinishPanel::updateRanges() {
  const double t1 = std::max(durationS(), last_t_);
  for (QCustomPlot* plot : std::as_const(plots_)) plot->xAxis->setRange(0.0, t1);
  QCPGraph* fd = graphs_["fd"];
  QCPGraph* ra_d = graphs_["ra_desired"];
  const ShopUnits& u = DisplayUnits::of(units_);
  const double fd_shown = u.fromBase(Quantity::Force, fd_reference_);
  if (fd_shown_) {
    fd->setData({0.0, t1}, {fd_shown, fd_shown}, true);
    fd->setName(tr("Reference F_d = %1 %2").arg(format(fd_shown), u.symbol(Quantity::Force)));
    fd->addToLegend();
  } else {
    fd->data()->clear();
    fd->removeFromLegend();
  }
  ra_d->setData({0.0, t1}, {ra_reference_, ra_reference_}, true);
  ra_d->setName(tr("Desired Ra_d = %1 \u00b5m").arg(format(ra_reference_)));

  // From zero (these signals are positive), 10 % headroom over the data and the reference lines.
  auto fit = [](QCPAxis* axis, Range r, std::initializer_list<double> extra, double fallback) {
    for (double v : extra) r.add(v);
    const double hi = r.any && r.hi > 0.0 ? r.hi : fallback;
    const double lo = r.any ? std::min(0.0, r.lo) : 0.0;
    axis->setRange(lo * 1.1, hi * 1.1);
  };
  fit(plots_[0]->yAxis, ranges_[0], {ra_reference_}, kMaxRaUm);
  fit(plots_[1]->yAxis, ranges_[1], {fd_shown_ ? fd_shown : 0.0}, 100.0);
  fit(plots_[2]->yAxis, ranges_[2], {}, 100.0);
  fit(plots_[3]->yAxis, ranges_[3], {}, 1000.0);
}

void SurfaceFinishPanel::replotAll() {
  for (QCustomPlot* plot : std::as_const(plots_)) plot->replot(QCustomPlot::rpQueuedReplot);
}

QString SurfaceFinishPanel::summaryText(const QString& key) const {
  const QLabel* label = summary_.value(key, nullptr);
  return label ? label->text() : QString();
}

int SurfaceFinishPanel::graphDataCount(const QString& graph) const {
  const QCPGraph* g = graphs_.value(graph, nullptr);
  return g ? g->dataCount() : -1;
}

Qt::PenStyle SurfaceFinishPanel::graphPenStyle(const QString& graph) const {
  const QCPGraph* g = graphs_.value(graph, nullptr);
  return g ? g->pen().style() : Qt::NoPen;
}

int SurfaceFinishPanel::graphPlot(const QString& graph) const {
  const QCPGraph* g = graphs_.value(graph, nullptr);
  return g ? static_cast<int>(plots_.indexOf(g->parentPlot())) : -1;
}

double SurfaceFinishPanel::valueAxisUpper(int plot) const {
  return plot >= 0 && plot < plots_.size() ? plots_[plot]->yAxis->range().upper : 0.0;
}

std::optional<std::pair<double, double>> SurfaceFinishPanel::graphValueRange(const QString& graph) const {
  const QCPGraph* g = graphs_.value(graph, nullptr);
  if (!g || g->dataCount() == 0) return std::nullopt;
  bool found = false;
  const QCPRange r = g->getValueRange(found);
  return found ? std::optional(std::pair(r.lower, r.upper)) : std::nullopt;
}

QString SurfaceFinishPanel::graphName(const QString& graph) const {
  const QCPGraph* g = graphs_.value(graph, nullptr);
  return g ? g->name() : QString();
}

bool SurfaceFinishPanel::graphInLegend(const QString& graph) const {
  QCPGraph* g = graphs_.value(graph, nullptr);
  return g && g->parentPlot()->legend->hasItemWithPlottable(g);
}

QStringList SurfaceFinishPanel::axisLabels() const {
  QStringList out;
  for (const QCustomPlot* plot : plots_) out << plot->xAxis->label() << plot->yAxis->label();
  return out;
}

double SurfaceFinishPanel::timeAxisUpper() const {
  return plots_.front()->xAxis->range().upper;
}

}  // namespace mx::widgets
