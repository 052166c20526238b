#include "requirements_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <algorithm>
#include <cmath>

#include "indicator_gauge.h"

namespace mx::widgets {

namespace {

struct ObjectiveSpec {
  const char* name;
  const char* unit;  // of RequirementView; MRR is shown in the shop unit instead
  const char* suffix;
  double max;
  int decimals;
  double step;
  const char* tip;
};

constexpr int kMrr = 1;
constexpr ObjectiveSpec kObjectives[RequirementsPanel::kObjectiveCount] = {
    {"Tool life TOL", "min", " min", 1e6, 1, 1.0, "Tool life from the Taylor model (eq. 10), in minutes"},
    {"MRR", "cm\u00b3/s", " cm\u00b3/s", 1e4, 4, 0.1, "Material removal rate a b s_t n_t N (eq. 11)"},
    {"Roughness SURF", "\u00b5m", " \u00b5m", 1000.0, 3, 0.1, "Surface roughness (eq. 12), in \u00b5m"},
    {"Robustness ROS", "\u2013", "", 10.0, 3, 0.01,
     "Robustness: normalised distance to the stability boundary (eq. 13), dimensionless"},
};

bool validObjective(int objective) {
  return objective >= 0 && objective < RequirementsPanel::kObjectiveCount;
}

const ObjectiveSpec& spec(int objective) {
  return kObjectives[std::clamp(objective, 0, RequirementsPanel::kObjectiveCount - 1)];
}

QString colorStyle(const QColor& color) {
  return QString("QLabel { color: %1; font-weight: bold; }").arg(color.name());
}

QColor warningColor() {
  return QColor(230, 120, 0);
}

}  // namespace

// In the units the spin boxes show (those of the last applyObjective()).
double RequirementsPanel::toShown(int objective, double value) const {
  if (objective != kMrr) return value;
  return shown_units_.fromBase(Quantity::RemovalRate, cm3PerMinFromCm3PerS(value));
}

// The spin box's value in RequirementView units; `stored` when the box still shows it (a unit
// conversion would otherwise move a bound the user did not touch).
double RequirementsPanel::fromShown(int objective, const QDoubleSpinBox* spin, double stored) const {
  const int d = spin->decimals();
  if (QString::number(spin->value(), 'f', d) == QString::number(toShown(objective, stored), 'f', d)) return stored;
  if (objective != kMrr) return spin->value();
  return cm3PerSFromCm3PerMin(shown_units_.toBase(Quantity::RemovalRate, spin->value()));
}

QString RequirementsPanel::shownUnit(int objective) const {
  return objective == kMrr ? shown_units_.symbol(Quantity::RemovalRate) : unit(objective);
}

void RequirementsPanel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &RequirementsPanel::refreshUnits);
}

void RequirementsPanel::refreshUnits() {
  if (validObjective(shown_objective_)) storeShownBounds();  // in the units shown so far
  shown_units_ = DisplayUnits::of(units_);
  const QSignalBlocker block(objective_);
  objective_->setItemText(kMrr, QString("%1 [%2]").arg(tr(kObjectives[kMrr].name), shownUnit(kMrr)));
  if (!validObjective(shown_objective_)) return;
  const int objective = shown_objective_;
  shown_objective_ = -1;  // applyObjective() must not store them again
  applyObjective(objective);
}

void RequirementsPanel::storeShownBounds() {
  auto& b = bounds_[static_cast<std::size_t>(shown_objective_)];
  b = {fromShown(shown_objective_, lo_, b[0]), fromShown(shown_objective_, hi_, b[1])};
}

QString RequirementsPanel::unit(int objective) {
  return validObjective(objective) ? QString::fromUtf8(kObjectives[objective].unit) : QString();
}

QString RequirementsPanel::suffix(int objective) {
  return validObjective(objective) ? QString::fromUtf8(kObjectives[objective].suffix) : QString();
}

QString RequirementsPanel::objectiveName(int objective) {
  return validObjective(objective) ? QString::fromUtf8(kObjectives[objective].name) : QString();
}

RequirementsPanel::RequirementsPanel(QWidget* parent)
    : QWidget(parent),
      enable_(new QCheckBox(tr("Require"), this)),
      objective_(new QComboBox(this)),
      lo_(new QDoubleSpinBox(this)),
      hi_(new QDoubleSpinBox(this)),
      lo_label_(new QLabel(this)),
      hi_label_(new QLabel(this)),
      auto_(new QPushButton(tr("Automatic weights (Rule 12)"), this)),
      status_(new QLabel(this)) {
  setToolTip(
      tr("Rule 11: keep one objective of the selected point inside [lower, upper] by changing only "
         "its weight; Rule 12: choose the weights automatically."));
  enable_->setObjectName("requirement_enable");
  objective_->setObjectName("requirement_objective");
  lo_->setObjectName("requirement_lo");
  hi_->setObjectName("requirement_hi");
  auto_->setObjectName("requirement_auto_weights");
  status_->setObjectName("requirement_status");
  lo_label_->setObjectName("requirement_lo_label");
  hi_label_->setObjectName("requirement_hi_label");

  enable_->setToolTip(
      tr("Rule 11: when checked, the selection must keep the chosen objective inside the "
         "bounds; only that objective's weight is changed (the others keep their "
         "proportions, Rule 13.2). A band the weights cannot reach is reported below."));
  objective_->setToolTip(
      tr("The objective the requirement bounds: tool life TOL [min], MRR (shop units), "
         "roughness SURF [\u00b5m] or robustness ROS [\u2013]."));
  for (int i = 0; i < kObjectiveCount; ++i) {
    objective_->addItem(QString("%1 [%2]").arg(tr(kObjectives[i].name), shownUnit(i)));
    objective_->setItemData(i, tr(kObjectives[i].tip), Qt::ToolTipRole);
  }
  for (QDoubleSpinBox* spin : {lo_, hi_}) {
    spin->setKeyboardTracking(false);
    spin->setAccelerated(true);
  }
  lo_->setToolTip(
      tr("Lower bound of the required objective (inclusive). Typing a value above the upper "
         "bound moves the upper bound to it."));
  hi_->setToolTip(
      tr("Upper bound of the required objective (inclusive). Typing a value below the lower "
         "bound moves the lower bound to it."));
  lo_label_->setToolTip(lo_->toolTip());
  hi_label_->setToolTip(hi_->toolTip());
  lo_label_->setBuddy(lo_);
  hi_label_->setBuddy(hi_);
  auto_->setToolTip(
      tr("Rule 12: projected gradient ascent of the weights, J(w) = max over Q of w\u00b7n(q), "
         "renormalised after each step (Rule 13.1). The result replaces the current weights."));
  status_->setToolTip(
      tr("Result of the last selection: whether the requirement is met and whether Rule 11 "
         "or Rule 12 changed the weights."));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  for (int i = 0; i < kObjectiveCount; ++i) bounds_[static_cast<std::size_t>(i)] = {0.0, kObjectives[i].max};

  auto* grid = new QGridLayout(this);
  grid->addWidget(enable_, 0, 0);
  grid->addWidget(objective_, 0, 1);
  grid->addWidget(lo_label_, 1, 0);
  grid->addWidget(lo_, 1, 1);
  grid->addWidget(hi_label_, 2, 0);
  grid->addWidget(hi_, 2, 1);
  grid->addWidget(auto_, 3, 0, 1, 2);
  grid->addWidget(status_, 4, 0, 1, 2);
  grid->setColumnStretch(1, 1);
  grid->setRowStretch(5, 1);

  {
    const QSignalBlocker block(objective_);
    objective_->setCurrentIndex(kDefaultObjective);
  }
  applyObjective(kDefaultObjective);
  updateEnabled();

  connect(enable_, &QCheckBox::toggled, this, [this] {
    updateEnabled();
    emit requirementChanged();
  });
  connect(objective_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (!validObjective(index) || index == shown_objective_) return;
    applyObjective(index);
    emit requirementChanged();
  });
  connect(lo_, &QDoubleSpinBox::valueChanged, this, [this] { onBoundEdited(true); });
  connect(hi_, &QDoubleSpinBox::valueChanged, this, [this] { onBoundEdited(false); });
  connect(auto_, &QPushButton::clicked, this, &RequirementsPanel::autoWeightsRequested);
}

std::optional<RequirementView> RequirementsPanel::requirement() const {
  if (!enable_->isChecked()) return std::nullopt;
  const auto& b = bounds_[static_cast<std::size_t>(shown_objective_)];
  return RequirementView{shown_objective_, fromShown(shown_objective_, lo_, b[0]),
                         fromShown(shown_objective_, hi_, b[1])};
}

void RequirementsPanel::setRequirement(const std::optional<RequirementView>& r) {
  const QSignalBlocker blockEnable(enable_);
  const QSignalBlocker blockObjective(objective_);
  const QSignalBlocker blockLo(lo_);
  const QSignalBlocker blockHi(hi_);
  enable_->setChecked(r.has_value());
  if (r) {
    const int objective = std::clamp(r->objective, 0, kObjectiveCount - 1);
    const double max = kObjectives[objective].max;
    auto clampBound = [max](double v) { return std::isfinite(v) ? std::clamp(v, 0.0, max) : (v > 0 ? max : 0.0); };
    double lo = std::isnan(r->lo) ? 0.0 : clampBound(r->lo);
    double hi = std::isnan(r->hi) ? max : clampBound(r->hi);
    if (lo > hi) std::swap(lo, hi);
    // Keep the bounds of the objective shown so far, then load the new ones.
    if (validObjective(shown_objective_)) storeShownBounds();
    bounds_[static_cast<std::size_t>(objective)] = {lo, hi};
    objective_->setCurrentIndex(objective);
    shown_objective_ = -1;  // applyObjective() must not overwrite the bounds just set
    applyObjective(objective);
  }
  updateEnabled();
}

void RequirementsPanel::applyObjective(int objective) {
  if (validObjective(shown_objective_)) storeShownBounds();
  const ObjectiveSpec& s = spec(objective);
  const auto& b = bounds_[static_cast<std::size_t>(objective)];
  const QString u = shownUnit(objective);
  const bool mrr = objective == kMrr;
  const QSignalBlocker blockLo(lo_);
  const QSignalBlocker blockHi(hi_);
  for (QDoubleSpinBox* spin : {lo_, hi_}) {
    // MRR: one decimal more than a readout, so that a typed bound keeps the resolution of cm³/s.
    spin->setDecimals(mrr ? shown_units_.decimals(Quantity::RemovalRate) + 1 : s.decimals);
    spin->setRange(0.0, toShown(objective, s.max));
    spin->setSingleStep(mrr ? 1.0 : s.step);
    spin->setSuffix(u.isEmpty() || u == QStringLiteral("\u2013") ? QString() : " " + u);
  }
  lo_->setValue(toShown(objective, b[0]));
  hi_->setValue(toShown(objective, b[1]));
  lo_label_->setText(tr("Lower bound [%1]").arg(u));
  hi_label_->setText(tr("Upper bound [%1]").arg(u));
  shown_objective_ = objective;
}

void RequirementsPanel::onBoundEdited(bool lower) {
  if (lo_->value() > hi_->value()) {
    QDoubleSpinBox* other = lower ? hi_ : lo_;
    const QSignalBlocker block(other);
    other->setValue(lower ? lo_->value() : hi_->value());
  }
  emit requirementChanged();
}

void RequirementsPanel::updateEnabled() {
  const bool on = enable_->isChecked();
  for (QWidget* w : std::initializer_list<QWidget*>{objective_, lo_, hi_, lo_label_, hi_label_}) w->setEnabled(on);
}

void RequirementsPanel::showStatus(const QString& text, const QString& style) {
  status_->setText(text);
  status_->setStyleSheet(style);
}

void RequirementsPanel::setStatus(bool satisfied, bool weights_changed) {
  QString text = satisfied ? tr("Requirement met") : tr("Requirement not reachable by the weights alone");
  if (weights_changed) text += satisfied ? tr(": weights changed by Rule 11") : tr(" (weights changed by Rule 11)");
  showStatus(text, colorStyle(satisfied ? IndicatorGauge::okColor() : IndicatorGauge::alarmColor()));
}

void RequirementsPanel::clearStatus() {
  showStatus(QString(), QString());
}

void RequirementsPanel::setAutoWeightsResult(int iterations, bool converged) {
  const QString count = iterations == 1 ? tr("1 iteration") : tr("%1 iterations").arg(iterations);
  showStatus(converged ? tr("Automatic weights (Rule 12): converged after %1").arg(count)
                       : tr("Automatic weights (Rule 12): not converged after %1").arg(count),
             colorStyle(converged ? IndicatorGauge::okColor() : warningColor()));
}

}  // namespace mx::widgets
