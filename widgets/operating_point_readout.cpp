#include "operating_point_readout.h"

#include <QFormLayout>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

#include "glossary.h"

namespace mx::widgets {

OperatingPointReadout::OperatingPointReadout(QWidget* parent)
    : QWidget(parent), verdict_(new QLabel(this)), agreement_(new QLabel(this)) {
  auto* outer = new QVBoxLayout(this);
  verdict_->setObjectName("readout_verdict");
  verdict_->setAlignment(Qt::AlignCenter);
  verdict_->setMinimumHeight(32);
  verdict_->setToolTip(
      tr("The lobes' verdict: stable below alpha times the delta-margined lobe (Rule 1), marginal up to 5 % above "
         "the lobe, unstable beyond"));
  outer->addWidget(verdict_);
  agreement_->setObjectName("readout_agreement");
  agreement_->setWordWrap(true);
  agreement_->setStyleSheet("color: #8a5a00;");
  agreement_->hide();
  outer->addWidget(agreement_);
  auto* form = new QFormLayout;
  form->setObjectName("readout_form");
  form->setLabelAlignment(Qt::AlignRight);
  outer->addLayout(form);
  outer->addStretch(1);
  setLayout(outer);
  const struct {
    const char* key;
    const char* label;
    const char* tip;
  } rows[] = {
      {"tool", "Tool", "The tool whose lobes are evaluated"},
      {"speed", "Spindle speed N", "Spindle speed of the operating point"},
      {"depth", "Axial depth b", "Axial depth of cut of the operating point"},
      {"feed", "Feed per tooth s_t", "Feed per tooth used for power and MRR"},
      {"surface_speed", "Surface speed v_c", "Cutting speed at the tool's diameter, v_c = \u03c0 D N"},
      {"feed_rate", "Feed rate v_f", "Table feed rate v_f = s_t n_t N"},
      {"power", "Peak power P", "Peak cutting power over a tooth period, v * sum F_t (Pareto paper eq. 8)"},
      {"power_fraction", "P / P_spindle", "Peak power as a fraction of the spindle power"},
      {"force", "Peak force F", "Peak resultant cutting force over a tooth period (rigid tool)"},
      {"force_fraction", "F / F_allow",
       "Peak force as a fraction of the tool's allowable force (tools[].max_force_N, else the control section's "
       "breakage limit; Pareto paper Rule 3)"},
      {"mrr", "MRR", "Material removal rate a * b * s_t * n_t * N"},
      {"blim", "b_lim(N)", "Alpha times the delta-margined stability limit at this speed"},
      {"dns", "\u0394N_s", "Spindle speed security change: distance in speed to the lobes (2006, section 3.B)"},
      {"ros", "ROS",
       "Robustness: the smallest relative change of speed and depth that reaches the margined stability boundary (1 = "
       "the depth could double; negative when unstable)"},
      {"simulation", "Simulation",
       "The time-domain simulation of this point (Live simulation dock): eta = 1 means no growth of the vibration"},
  };
  for (const auto& r : rows) values_.insert(r.key, addRow(r.key, tr(r.label), tr(r.tip)));
  // What's This (Shift+F1) on the symbols of the glossary, label and value alike.
  const std::pair<const char*, Term> terms[] = {{"dns", Term::DeltaNs}, {"ros", Term::Ros}, {"simulation", Term::Eta}};
  for (const auto& [key, term] : terms) {
    values_[key]->setWhatsThis(glossaryText(term));
    form->labelForField(values_[key])->setWhatsThis(glossaryText(term));
  }
  refresh();
}

QLabel* OperatingPointReadout::addRow(const QString& key, const QString& label, const QString& tooltip) {
  auto* form = findChild<QFormLayout*>("readout_form");
  auto* name = new QLabel(label + ":", this);
  auto* value = new QLabel(this);
  value->setObjectName("readout_" + key);
  value->setTextInteractionFlags(Qt::TextSelectableByMouse);
  name->setToolTip(tooltip);
  value->setToolTip(tooltip);
  form->addRow(name, value);
  return value;
}

void OperatingPointReadout::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &OperatingPointReadout::refresh);
}

void OperatingPointReadout::setReadout(const PointReadout& readout) {
  readout_ = readout;
  refresh();
}

void OperatingPointReadout::setSimulation(const SimulationCheck& check) {
  simulation_ = check;
  refreshSimulation();
}

QString OperatingPointReadout::agreementNote() const {
  return agreement_->isHidden() ? QString() : agreement_->text();
}

void OperatingPointReadout::refreshSimulation() {
  const SimulationCheck& s = simulation_;
  QString text;
  switch (s.state) {
    case SimulationCheck::State::None:
      text = tr("not run for this point");
      break;
    case SimulationCheck::State::Running:
      text = tr("running...");
      break;
    case SimulationCheck::State::Done:
      text = (s.chatter ? tr("CHATTER (\u03b7 = %1)") : tr("STABLE (\u03b7 = %1)")).arg(s.eta, 0, 'f', 3);
      break;
  }
  values_["simulation"]->setText(text);
  // Marginal points are where the two may differ: no note. A definite verdict the run contradicts gets one.
  const PointReadout& r = readout_;
  const bool done = s.state == SimulationCheck::State::Done && r.valid && !r.marginal;
  const bool disagree = done && r.stable == s.chatter;
  agreement_->setVisible(disagree);
  if (!disagree) return;
  agreement_->setText(
      tr("The lobes say %1, the simulation says %2 (\u03b7 = %3). The verdict follows the lobes: they are the "
         "limit of the linear model, while a 60-revolution run from one start can miss slow growth or stop at "
         "contact loss.")
          .arg(r.stable ? tr("STABLE") : tr("UNSTABLE"), s.chatter ? tr("CHATTER") : tr("STABLE"))
          .arg(s.eta, 0, 'f', 3));
}

QString OperatingPointReadout::text(const QString& field) const {
  if (field == "verdict") return verdict_->text();
  return values_.contains(field) ? values_[field]->text() : QString();
}

void OperatingPointReadout::refresh() {
  const PointReadout& r = readout_;
  const ShopUnits& units = DisplayUnits::of(units_);
  auto len = [&](double mm) { return units.format(Quantity::Length, mm); };
  values_["tool"]->setText(r.tool_id.isEmpty() ? "\u2014" : r.tool_id);
  values_["speed"]->setText(QString("%1 rpm").arg(r.speed_rpm, 0, 'f', 0));
  values_["depth"]->setText(len(r.depth_mm));
  values_["feed"]->setText(units.format(Quantity::ChipLoad, r.feed_mm_per_tooth));
  values_["surface_speed"]->setText(units.format(Quantity::SurfaceSpeed, r.surface_speed_m_min));
  values_["feed_rate"]->setText(units.format(Quantity::Feed, r.feed_rate_mm_min));
  values_["power"]->setText(units.format(Quantity::Power, r.peak_power_w));
  values_["power_fraction"]->setText(r.power_limit_w > 0 ? tr("%1 % of %2")
                                                               .arg(100.0 * r.powerFraction(), 0, 'f', 1)
                                                               .arg(units.format(Quantity::Power, r.power_limit_w))
                                                         : tr("no spindle limit"));
  values_["force"]->setText(units.format(Quantity::Force, r.peak_force_n));
  values_["force_fraction"]->setText(r.force_limit_n > 0 ? tr("%1 % of %2")
                                                               .arg(100.0 * r.forceFraction(), 0, 'f', 1)
                                                               .arg(units.format(Quantity::Force, r.force_limit_n))
                                                         : tr("no tool force limit"));
  values_["mrr"]->setText(units.format(Quantity::RemovalRate, cm3PerMinFromMm3PerS(r.mrr_mm3_per_s)));
  const bool valid = r.valid;
  values_["blim"]->setText(!valid ? "\u2014" : std::isfinite(r.blim_mm) ? len(r.blim_mm) : tr("none below the cap"));
  values_["dns"]->setText(valid ? QString("%1 rpm").arg(r.delta_ns_rpm, 0, 'f', 0) : "\u2014");
  values_["ros"]->setText(valid && std::isfinite(r.ros) ? QString::number(r.ros, 'f', 4) : "\u2014");
  QString verdict, color;
  if (!valid) {
    verdict = r.message.isEmpty() ? tr("No operating point") : r.message;
    color = "#777777";
  } else if (r.marginal) {
    verdict = tr("MARGINAL \u2014 within 5 % of the stability limit");
    color = "#b08000";
  } else if (!r.stable) {
    verdict = tr("UNSTABLE \u2014 chatter expected");
    color = "#c81414";
  } else if (!r.powerOk()) {
    verdict = tr("Stable, but spindle power exceeded");
    color = "#e67800";
  } else if (!r.forceOk()) {
    verdict = tr("Stable, but tool force limit exceeded");
    color = "#e67800";
  } else {
    verdict = tr("STABLE");
    color = "#1e961e";
  }
  verdict_->setText(verdict);
  verdict_->setStyleSheet(QString("QLabel { color: white; background: %1; font-weight: bold; padding: 6px; "
                                  "border-radius: 4px; }")
                              .arg(color));
  refreshSimulation();
}

}  // namespace mx::widgets
