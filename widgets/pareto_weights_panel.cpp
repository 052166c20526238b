#include "pareto_weights_panel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <cmath>
#include <span>

#include "weights_panel.h"

namespace mx::widgets {

namespace {

struct RowSpec {
  const char* label;
  const char* tip;
};

constexpr RowSpec kRows[4] = {
    {"w_TOL tool life",
     "w_TOL: weight of the tool-life score (Taylor model, eq. 10; higher is better) "
     "(dimensionless, 0..1)"},
    {"w_MRR removal rate",
     "w_MRR: weight of the material-removal-rate score (eq. 11; higher is better) "
     "(dimensionless, 0..1)"},
    {"w_SURF roughness",
     "w_SURF: weight of the surface-roughness score (eq. 12; lower roughness scores "
     "higher) (dimensionless, 0..1)"},
    {"w_ROS robustness",
     "w_ROS: weight of the robustness score, the distance to the stability boundary "
     "(eq. 13; higher is better) (dimensionless, 0..1)"},
};

}  // namespace

void ParetoWeightsPanel::moveWeight(Weights& weights, std::size_t index, double value) {
  WeightsPanel::moveWeight(std::span<double>(weights), index, value);
}

ParetoWeightsPanel::ParetoWeightsPanel(QWidget* parent) : QWidget(parent) {
  setToolTip(
      tr("Weights of the Pareto cost J = sum w_i n_i over the normalised scores (Rule 9); they "
         "always sum to 1 and choose the point of the Pareto set."));
  auto* grid = new QGridLayout(this);
  for (std::size_t i = 0; i < 4; ++i) {
    const int row = static_cast<int>(i);
    const QString tip = tr(kRows[i].tip);
    auto* label = new QLabel(tr(kRows[i].label) + tr(" [\u2013]"), this);
    label->setToolTip(tip);
    auto* slider = new QSlider(Qt::Horizontal, this);
    slider->setRange(0, kSliderSteps);
    slider->setSingleStep(10);
    slider->setPageStep(100);
    slider->setToolTip(tip + tr("\nDrag to change; the other weights are rescaled to keep the sum 1."));
    auto* spin = new QDoubleSpinBox(this);
    spin->setRange(0.0, 1.0);
    spin->setDecimals(3);
    spin->setSingleStep(0.01);
    spin->setKeyboardTracking(false);
    spin->setToolTip(tip + tr("\nType a value; the other weights are rescaled to keep the sum 1."));
    slider->setObjectName(QString("pareto_weight_%1_slider").arg(row));
    spin->setObjectName(QString("pareto_weight_%1_spin").arg(row));
    label->setBuddy(spin);
    grid->addWidget(label, row, 0);
    grid->addWidget(slider, row, 1);
    grid->addWidget(spin, row, 2);
    sliders_[i] = slider;
    spins_[i] = spin;
    connect(slider, &QSlider::valueChanged, this,
            [this, i, slider](int v) { userSet(i, static_cast<double>(v) / kSliderSteps, !slider->isSliderDown()); });
    connect(slider, &QSlider::sliderReleased, this, &ParetoWeightsPanel::commitIfChanged);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, i](double v) { userSet(i, v, true); });
  }
  grid->setColumnStretch(1, 1);
  refresh();
}

QSlider* ParetoWeightsPanel::slider(int index) const {
  return index >= 0 && index < 4 ? sliders_[static_cast<std::size_t>(index)] : nullptr;
}

QDoubleSpinBox* ParetoWeightsPanel::spinBox(int index) const {
  return index >= 0 && index < 4 ? spins_[static_cast<std::size_t>(index)] : nullptr;
}

void ParetoWeightsPanel::setWeights(const Weights& weights) {
  weights_ = weights;
  bool ok = true;
  double sum = 0.0;
  for (double v : weights_) {
    ok = ok && std::isfinite(v) && v >= 0.0;
    sum += v;
  }
  if (!ok || std::abs(sum - 1.0) > 1e-9) moveWeight(weights_, 0, ok && sum > 0.0 ? weights_[0] / sum : 1.0);
  committed_ = weights_;
  refresh();
}

void ParetoWeightsPanel::userSet(std::size_t index, double value, bool commit) {
  moveWeight(weights_, index, value);
  refresh();
  emit weightsChanged(weights_);
  if (commit) commitIfChanged();
}

void ParetoWeightsPanel::commitIfChanged() {
  if (weights_ == committed_) return;
  committed_ = weights_;
  emit weightsCommitted(weights_);
}

void ParetoWeightsPanel::refresh() {
  for (std::size_t i = 0; i < 4; ++i) {
    const QSignalBlocker blockSlider(sliders_[i]);
    const QSignalBlocker blockSpin(spins_[i]);
    if (!sliders_[i]->isSliderDown()) sliders_[i]->setValue(static_cast<int>(std::lround(weights_[i] * kSliderSteps)));
    spins_[i]->setValue(weights_[i]);
  }
}

}  // namespace mx::widgets
