#include "monitoring_panel.h"

#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

#include "glossary.h"
#include "indicator_gauge.h"

namespace mx::widgets {

namespace {

const QString kMissing = QStringLiteral("\u2013");

struct RowSpec {
  const char* key;
  const char* label;  // %1: the shop unit of `quantity`
  const char* tip;
  std::optional<Quantity> quantity = std::nullopt;
};

constexpr RowSpec kRows[] = {
    {"peak_force_n", "Peak force [%1]", "Largest cutting force magnitude over the last revolutions", Quantity::Force},
    {"peak_power_w", "Peak power [%1]",
     "Peak cutting power over a tooth period, v * sum F_t (Pareto paper eq. 8), and the spindle power limit; "
     "red when the limit is exceeded",
     Quantity::Power},
    {"feed_velocity_mm_s", "Feed rate [%1]", "Table feed rate s_t n_t N", Quantity::Feed},
    {"mrr_cm3_s", "MRR [%1]", "Material removal rate a b s_t n_t N (eq. 11)", Quantity::RemovalRate},
    {"tol_min", "Tool life TOL [min]", "Tool life from the Taylor model (eq. 10)"},
    {"surf_um", "Roughness SURF [\u00b5m]", "Surface roughness (eq. 12)"},
    {"ros", "Robustness ROS [\u2013]",
     "Normalised distance to the stability boundary (eq. 13); negative when the point is unstable"},
    {"eta", "eta [\u2013]",
     "Chatter indicator eta = max |F_dyn| / max |F_static| (2006 paper, eq. 11); chatter from 1.3, about 1 when "
     "stable"},
    {"chip_ratio", "Chip ratio [\u2013] (Rule 15: \u2265 1.25)",
     "Rule 15: chip ratio = max h_dyn / max h_static, the largest dynamic over the largest static chip thickness; "
     "chatter when it reaches 1.25 (shown red)"},
    {"tooth_passing_hz", "Tooth passing [Hz]", "Tooth-passing frequency n_t N / 60"},
    {"chatter_frequency_hz", "Chatter frequency [Hz]",
     "Largest peak of the vibration spectrum outside the tooth-passing harmonics: the chatter frequency f_c "
     "(Rule 16 suggests N = 60 f_c / (n_t k))"},
};

QString verdictStyle(const QColor& color) {
  return QString("QLabel { background: %1; color: white; padding: 6px; border-radius: 4px; font-weight: bold; }")
      .arg(color.name());
}

bool finite(std::optional<double> v) {
  return v && std::isfinite(*v);
}

std::optional<double> shown(const ShopUnits& units, Quantity q, std::optional<double> base) {
  return base ? std::optional<double>(units.fromBase(q, *base)) : std::nullopt;
}

std::optional<double> scaled(std::optional<double> v, double factor) {
  return v ? std::optional<double>(*v * factor) : std::nullopt;
}

}  // namespace

QString MonitoringPanel::formatNumber(std::optional<double> v) {
  if (!finite(v)) return kMissing;
  const double x = *v;
  if (x == 0.0) return QStringLiteral("0");
  const double a = std::abs(x);
  if (a < 1e-3 || a >= 1e9) return QString::number(x, 'g', 4);
  // 4 significant digits, after rounding (9999.6 -> "10000", 0.99996 -> "1.000").
  int exponent = static_cast<int>(std::floor(std::log10(a)));
  const double scale = std::pow(10.0, 3 - exponent);
  if (std::round(a * scale) >= 1e4) ++exponent;
  return QString::number(x, 'f', std::max(0, 3 - exponent));
}

MonitoringPanel::MonitoringPanel(QWidget* parent)
    : QWidget(parent), verdict_(new QLabel(this)), peaks_(new QTableWidget(0, 4, this)) {
  setToolTip(tr("Rule 17: monitoring signals of the running point and the identified spectrum peaks."));
  auto* outer = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  form->setLabelAlignment(Qt::AlignRight);
  outer->addLayout(form);
  for (const RowSpec& r : kRows) {
    const QString tip = tr(r.tip);
    auto* name = new QLabel(this);
    names_.insert(r.key, name);
    auto* value = new QLabel(this);
    value->setObjectName(QString("monitoring_%1").arg(r.key));
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    name->setToolTip(tip);
    value->setToolTip(tip);
    form->addRow(name, value);
    values_.insert(r.key, value);
  }
  for (const auto& [key, term] : {std::pair{"ros", Term::Ros}, std::pair{"eta", Term::Eta}}) {
    names_[key]->setWhatsThis(glossaryText(term));
    values_[key]->setWhatsThis(glossaryText(term));
  }

  verdict_->setObjectName("monitoring_verdict");
  verdict_->setAlignment(Qt::AlignCenter);
  verdict_->setToolTip(
      tr("Rule 15 verdict: chatter when the chip-thickness ratio reaches 1.25 (or the "
         "simulation detects it); Rule 16 then suggests the speed 60 f_c / (n_t k)."));
  outer->addWidget(verdict_);

  peaks_->setObjectName("monitoring_peaks");
  peaks_->setToolTip(
      tr("Rule 17: the largest peaks of the force spectrum, by decreasing amplitude. Kind: a "
         "multiple k of the tooth-passing frequency (forced), of the spindle frequency (run-out), "
         "or non-harmonic (chatter); Harmonic is k."));
  peaks_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  peaks_->setSelectionBehavior(QAbstractItemView::SelectRows);
  peaks_->setSortingEnabled(false);
  peaks_->setAlternatingRowColors(true);
  peaks_->verticalHeader()->hide();
  peaks_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  peaks_->horizontalHeader()->setStretchLastSection(true);
  outer->addWidget(peaks_, 1);
  refreshUnits();
  clear();
}

void MonitoringPanel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &MonitoringPanel::refreshUnits);
}

void MonitoringPanel::refreshUnits() {
  const ShopUnits& units = DisplayUnits::of(units_);
  for (const RowSpec& r : kRows)
    names_[r.key]->setText((r.quantity ? tr(r.label).arg(units.symbol(*r.quantity)) : tr(r.label)) + ":");
  peaks_->setHorizontalHeaderLabels({tr("Frequency [Hz]"), tr("Amplitude [%1]").arg(units.symbol(Quantity::Force)),
                                     tr("Kind"), tr("Harmonic [\u2013]")});
  if (shown_values_) setValues(*shown_values_);
  setPeaks(QVector<MonitoringPeak>(shown_peaks_));
}

QString MonitoringPanel::valueText(const QString& key) const {
  if (key == QLatin1String("verdict")) return verdict_->text();
  const QLabel* label = values_.value(key, nullptr);
  return label ? label->text() : QString();
}

QLabel* MonitoringPanel::valueLabel(const QString& key) const {
  if (key == QLatin1String("verdict")) return verdict_;
  return values_.value(key, nullptr);
}

void MonitoringPanel::setAlarm(QLabel* label, bool alarm) {
  label->setStyleSheet(
      alarm ? QString("QLabel { color: %1; font-weight: bold; }").arg(IndicatorGauge::alarmColor().name()) : QString());
}

void MonitoringPanel::setValues(const MonitoringValues& v) {
  shown_values_ = v;
  const ShopUnits& units = DisplayUnits::of(units_);
  const std::pair<const char*, std::optional<double>> plain[] = {
      {"peak_force_n", shown(units, Quantity::Force, v.peak_force_n)},
      {"feed_velocity_mm_s", shown(units, Quantity::Feed, scaled(v.feed_velocity_mm_s, 60.0))},
      {"mrr_cm3_s", shown(units, Quantity::RemovalRate, scaled(v.mrr_cm3_s, 60.0))},
      {"tol_min", v.tol_min},
      {"surf_um", v.surf_um},
      {"ros", v.ros},
      {"eta", v.eta},
      {"chip_ratio", v.chip_ratio},
      {"tooth_passing_hz", v.tooth_passing_hz},
      {"chatter_frequency_hz", v.chatter_frequency_hz},
  };
  for (const auto& [key, value] : plain) values_[key]->setText(formatNumber(value));
  setAlarm(values_["chip_ratio"], finite(v.chip_ratio) && *v.chip_ratio >= kChipRatioThreshold);
  setAlarm(values_["ros"], finite(v.ros) && *v.ros < 0.0);

  QLabel* power = values_["peak_power_w"];
  const bool has_limit = finite(v.power_limit_w) && *v.power_limit_w > 0.0;
  QString text = formatNumber(shown(units, Quantity::Power, v.peak_power_w));
  text += has_limit
              ? tr(" of %1 %2")
                    .arg(formatNumber(shown(units, Quantity::Power, v.power_limit_w)), units.symbol(Quantity::Power))
              : QString();
  power->setText(text);
  setAlarm(power, has_limit && finite(v.peak_power_w) && *v.peak_power_w > *v.power_limit_w);

  // "Stable" needs evidence: a chatter indicator (no simulation yet: "–").
  if (!v.chatter && !finite(v.eta) && !finite(v.chip_ratio)) {
    verdict_->setText(kMissing);
    verdict_->setStyleSheet(verdictStyle(palette().color(QPalette::Mid)));
    return;
  }
  verdict_->setText(v.chatter ? tr("Chatter (Rule 15)") : tr("Stable"));
  verdict_->setStyleSheet(verdictStyle(v.chatter ? IndicatorGauge::alarmColor() : IndicatorGauge::okColor()));
}

void MonitoringPanel::setPeaks(const QVector<MonitoringPeak>& peaks) {
  shown_peaks_ = peaks;
  const ShopUnits& units = DisplayUnits::of(units_);
  peaks_->setRowCount(0);
  peaks_->setRowCount(static_cast<int>(peaks.size()));
  for (int row = 0; row < peaks_->rowCount(); ++row) {
    const MonitoringPeak& p = peaks[row];
    const QString cells[] = {formatNumber(p.frequency_hz), formatNumber(units.fromBase(Quantity::Force, p.amplitude_n)),
                             p.kind, p.harmonic > 0 ? QString::number(p.harmonic) : kMissing};
    for (int col = 0; col < 4; ++col) {
      auto* item = new QTableWidgetItem(cells[col]);
      item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
      if (col != 2) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      peaks_->setItem(row, col, item);
    }
  }
}

void MonitoringPanel::clear() {
  shown_values_.reset();
  shown_peaks_.clear();
  for (QLabel* label : std::as_const(values_)) {
    label->setText(kMissing);
    setAlarm(label, false);
  }
  verdict_->setText(kMissing);
  verdict_->setStyleSheet(verdictStyle(palette().color(QPalette::Mid)));
  peaks_->setRowCount(0);
}

}  // namespace mx::widgets
