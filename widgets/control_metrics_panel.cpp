#include "control_metrics_panel.h"

#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>

#include "glossary.h"
#include "indicator_gauge.h"
#include "monitoring_panel.h"

namespace mx::widgets {

namespace {
const QString kMissing = QStringLiteral("\u2013");

QString num(double v) {
  return MonitoringPanel::formatNumber(v);
}
}  // namespace

ControlMetricsPanel::ControlMetricsPanel(QWidget* parent) : QWidget(parent), warning_(new QLabel(this)) {
  struct Row {
    const char* key;
    const char* label;
    const char* tip;
  };
  const Row rows[] = {
      {"overshoot", "Overshoot per depth step [%]:",
       "Peak force after each depth step above the reference, in % of the reference; for a downward step the "
       "undershoot"},
      {"settling_time", "Settling time [s]:", "Time for the force to stay within the band around the reference"},
      {"jc", "Cost J_c [N\u00b7s]:",
       "Eq. 34: area between the continuous plant output and the linear interpolation of its samples"},
      {"max_force", "Max. force [%1]:", "Largest continuous plant force over the run"},
      {"feed_range", "Feed range [%1]:", "Smallest and largest feed commanded (clamped to [0, f_max])"},
  };
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  form->setLabelAlignment(Qt::AlignRight);
  outer->addLayout(form);
  for (const Row& r : rows) {
    auto* value = new QLabel(this);
    value->setObjectName(QStringLiteral("control_metric_") + QLatin1String(r.key));
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    value->setToolTip(tr(r.tip));
    auto* label = new QLabel(tr(r.label), this);
    label->setToolTip(tr(r.tip));
    labels_.insert(QString::fromLatin1(r.key), label);
    form->addRow(label, value);
    values_.insert(QString::fromLatin1(r.key), value);
  }
  labels_["jc"]->setWhatsThis(glossaryText(Term::Jc));
  values_["jc"]->setWhatsThis(glossaryText(Term::Jc));
  warning_->setObjectName(QStringLiteral("control_metric_warning"));
  warning_->setWordWrap(true);
  warning_->setStyleSheet(QString("QLabel { background: %1; color: white; padding: 4px; border-radius: 4px; "
                                  "font-weight: bold; }")
                              .arg(IndicatorGauge::alarmColor().name()));
  outer->addWidget(warning_);
  relabel();
  clear();
}

void ControlMetricsPanel::setUnits(DisplayUnits* units) {
  const auto apply = [this] {
    relabel();
    if (metrics_) setMetrics(ControlMetricsView(*metrics_));
  };
  followUnits(this, units_, units, apply);
}

void ControlMetricsPanel::relabel() {
  const ShopUnits& u = DisplayUnits::of(units_);
  labels_["max_force"]->setText(tr("Max. force [%1]:").arg(u.symbol(Quantity::Force)));
  labels_["feed_range"]->setText(tr("Feed range [%1]:").arg(u.symbol(Quantity::Feed)));
}

QVector<QPair<double, double>> ControlMetricsPanel::depthSteps(const QVector<double>& depth_mm) {
  QVector<QPair<double, double>> steps;
  for (qsizetype i = 1; i < depth_mm.size(); ++i)
    if (std::isfinite(depth_mm[i]) && std::isfinite(depth_mm[i - 1]) && depth_mm[i] != depth_mm[i - 1])
      steps.push_back({depth_mm[i - 1], depth_mm[i]});
  return steps;
}

void ControlMetricsPanel::clear() {
  metrics_.reset();
  for (QLabel* label : std::as_const(values_)) label->setText(kMissing);
  overshoot_pct_.clear();
  has_metrics_ = false;
  warning_->clear();
  warning_->setVisible(false);
}

void ControlMetricsPanel::setDepthSteps(const QVector<QPair<double, double>>& from_to_mm) {
  steps_ = from_to_mm;
  showOvershoots();
}

void ControlMetricsPanel::setMetrics(const ControlMetricsView& m) {
  has_metrics_ = true;
  metrics_ = m;
  const ShopUnits& u = DisplayUnits::of(units_);
  const auto feed = [&u](double mm_s) { return u.fromBase(Quantity::Feed, perMinute(mm_s)); };
  overshoot_pct_ = m.overshoot_pct;
  showOvershoots();
  values_["settling_time"]->setText(num(m.settling_time_s));
  values_["jc"]->setText(num(m.jc_n_s));
  values_["max_force"]->setText(num(u.fromBase(Quantity::Force, m.max_force_n)));
  values_["feed_range"]->setText(std::isfinite(m.min_feed_mm_s) || std::isfinite(m.max_feed_mm_s)
                                     ? tr("%1 to %2").arg(num(feed(m.min_feed_mm_s)), num(feed(m.max_feed_mm_s)))
                                     : kMissing);
  warning_->setText(
      tr("Unstable zero: H_\u03b2 has a zero outside the unit circle, so the controller does not "
         "cancel it (slower tracking). Raise \u03b2 above the shaded region."));
  warning_->setVisible(m.unstable_zero);
}

void ControlMetricsPanel::showOvershoots() {
  QLabel* label = values_["overshoot"];
  if (!has_metrics_) return;
  if (overshoot_pct_.isEmpty()) {
    label->setText(kMissing);
    return;
  }
  QStringList lines;
  for (qsizetype i = 0; i < overshoot_pct_.size(); ++i) {
    QString line = tr("step %1: %2").arg(i + 1).arg(num(overshoot_pct_[i]));
    if (i < steps_.size()) {
      const auto [from, to] = steps_[i];
      const ShopUnits& u = DisplayUnits::of(units_);
      line += tr(" (%1 \u2192 %2 %3, %4)")
                  .arg(num(u.fromBase(Quantity::Length, from)), num(u.fromBase(Quantity::Length, to)),
                       u.symbol(Quantity::Length), to < from ? tr("undershoot") : tr("overshoot"));
    }
    lines << line;
  }
  label->setText(lines.join('\n'));
}

QString ControlMetricsPanel::valueText(const QString& key) const {
  if (key == QLatin1String("warning")) return warningShown() ? warning_->text() : QString();
  const QLabel* label = values_.value(key, nullptr);
  return label ? label->text() : QString();
}

bool ControlMetricsPanel::warningShown() const {
  return !warning_->isHidden();
}

}  // namespace mx::widgets
