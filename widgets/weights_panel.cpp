#include "weights_panel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ternary_picker.h"

namespace mx::widgets {

namespace {

// Compact margins and rows: the four groups and the triangle fit the right dock at 1920 x 1080.
constexpr int kMargin = 6;
constexpr int kRowSpacing = 2;

bool sameWeights(const CostWeights& a, const CostWeights& b) {
  return a.c == b.c && a.cr == b.cr && a.ct == b.ct && a.cf == b.cf;
}

}  // namespace

void WeightsPanel::moveWeight(std::span<double> w, std::size_t index, double value) {
  const std::size_t n = w.size();
  if (index >= n) return;
  value = std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0;
  if (n == 1) {
    w[0] = 1.0;
    return;
  }
  const double rest = 1.0 - value;
  double others = 0.0;
  for (std::size_t j = 0; j < n; ++j)
    if (j != index) others += std::max(w[j], 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    if (j == index) continue;
    w[j] = others > 0.0 ? rest * (std::max(w[j], 0.0) / others) : rest / static_cast<double>(n - 1);
  }
  w[index] = value;
  // Rounding residual to the largest of the others (it stays >= 0), or to the moved one when the
  // others are all zero: the sum is then 1 to the last ulp.
  std::size_t fix = index;
  for (std::size_t j = 0; j < n; ++j)
    if (j != index && w[j] > 0.0 && (fix == index || w[j] > w[fix])) fix = j;
  double sum = 0.0;
  for (double v : w) sum += v;
  w[fix] = std::max(0.0, w[fix] + (1.0 - sum));
}

WeightsPanel::WeightsPanel(QWidget* parent) : QWidget(parent), committed_(weights_) {
  ternary_ = new TernaryPicker(this);
  ternary_->setObjectName("weights_ternary");
  connect(ternary_, &TernaryPicker::weightsChanged, this, [this](const std::array<double, 3>& c) {
    weights_.c = c;
    refresh();
    emit weightsChanged(weights_);
  });
  connect(ternary_, &TernaryPicker::weightsCommitted, this, [this] { commitIfChanged(); });

  // The reset button beside the triangle, in the first group: the panel fits the right dock at 1080p
  // without scrolling.
  reset_ = new QPushButton(tr("Reset to project"), this);
  reset_->setObjectName("weights_reset");
  reset_->setToolTip(tr("Restore the weights saved in the project's expert section"));
  connect(reset_, &QPushButton::clicked, this, &WeightsPanel::resetRequested);
  auto* top = new QWidget(this);
  auto* top_row = new QHBoxLayout(top);
  top_row->setContentsMargins(0, 0, 0, 0);
  top_row->addWidget(ternary_, 1);
  top_row->addWidget(reset_, 0, Qt::AlignTop);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(kMargin, kMargin, kMargin, kMargin);
  layout->setSpacing(kMargin);
  layout->addWidget(
      addGroup(Group::Tool, tr("Tool cost weights c (eq. 13)"),
               tr("Weights of the tool cost C = c1 P/P_av + c2 MRR_max/MRR + c3 \u0394N_s,max/\u0394N_s; "
                  "they rank the tools (Rule 4) and choose q*. Always summing to 1."),
               {{"c1 power", "c1: weight of the spindle power term P / P_av (dimensionless, 0..1)"},
                {"c2 MRR", "c2: weight of the material removal rate term MRR_max / MRR (dimensionless, 0..1)"},
                {"c3 \u0394N_s",
                 "c3: weight of the speed security term \u0394N_s,max / \u0394N_s "
                 "(dimensionless, 0..1)"}},
               top),
      1);
  layout->addWidget(
      addGroup(Group::Resultant, tr("Resultant cost weights c_r (eq. 20)"),
               tr("Weights of C_resultant = c1r C + c2r C_t + c3r C_f, which chooses q** among the "
                  "simulated points (Rule 5). Always summing to 1."),
               {{"c1r tool cost C", "c1r: weight of the tool cost C (eq. 13) (dimensionless, 0..1)"},
                {"c2r time cost C_t", "c2r: weight of the time-response cost C_t (eq. 18) (dimensionless, 0..1)"},
                {"c3r spectrum cost C_f", "c3r: weight of the spectrum cost C_f (eq. 19) (dimensionless, 0..1)"}}));
  layout->addWidget(addGroup(Group::Time, tr("Time cost weights c_t (eq. 18)"),
                             tr("Weights of C_t = c1t t_s/t_s,max + c2t M_p/M_p,max; the two sum to 1."),
                             {{"c1t settling t_s", "c1t: weight of the settling time t_s (dimensionless, 0..1)"},
                              {"c2t overshoot M_p", "c2t: weight of the peak overshoot M_p (dimensionless, 0..1)"}}));
  layout->addWidget(addGroup(Group::Frequency, tr("Spectrum cost weights c_f (eq. 19)"),
                             tr("Weights of C_f = c1f R12h/R12h,max + c2f R1ch/R1ch,max; the two sum to 1."),
                             {{"c1f R12h", "c1f: weight of the harmonic ratio R12h (dimensionless, 0..1)"},
                              {"c2f R1ch", "c2f: weight of the chatter ratio R1ch (dimensionless, 0..1)"}}));
  refresh();
}

QGroupBox* WeightsPanel::addGroup(Group group, const QString& title, const QString& tip,
                                  const std::vector<RowSpec>& specs, QWidget* top) {
  auto* box = new QGroupBox(title, this);
  box->setToolTip(tip);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(kMargin, kMargin / 2, kMargin, kMargin / 2);
  grid->setVerticalSpacing(kRowSpacing);
  int line = 0;
  if (top) grid->addWidget(top, line++, 0, 1, 3);
  for (std::size_t i = 0; i < specs.size(); ++i, ++line) {
    const QString rowTip = tr(specs[i].tip);
    auto* label = new QLabel(tr(specs[i].label) + tr(" [\u2013]"), box);
    label->setToolTip(rowTip);
    auto* slider = new QSlider(Qt::Horizontal, box);
    slider->setRange(0, kSliderSteps);
    slider->setSingleStep(10);
    slider->setPageStep(100);
    slider->setToolTip(rowTip + tr("\nDrag to change; the other weights of the group are rescaled to keep the sum 1."));
    auto* spin = new QDoubleSpinBox(box);
    spin->setRange(0.0, 1.0);
    spin->setDecimals(3);
    spin->setSingleStep(0.01);
    spin->setKeyboardTracking(false);
    spin->setToolTip(rowTip);
    const QString name = QString("weight_%1_%2").arg(static_cast<int>(group)).arg(i);
    slider->setObjectName(name + "_slider");
    spin->setObjectName(name + "_spin");
    label->setBuddy(spin);
    grid->addWidget(label, line, 0);
    grid->addWidget(slider, line, 1);
    grid->addWidget(spin, line, 2);
    grid->setColumnStretch(1, 1);
    rows_.push_back({group, i, slider, spin});
    connect(slider, &QSlider::valueChanged, this, [this, group, i, slider](int v) {
      userSet(group, i, static_cast<double>(v) / kSliderSteps, !slider->isSliderDown());
    });
    connect(slider, &QSlider::sliderReleased, this, &WeightsPanel::commitIfChanged);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, group, i](double v) { userSet(group, i, v, true); });
  }
  return box;
}

std::span<double> WeightsPanel::values(Group group) {
  switch (group) {
    case Group::Tool:
      return weights_.c;
    case Group::Resultant:
      return weights_.cr;
    case Group::Time:
      return weights_.ct;
    case Group::Frequency:
      return weights_.cf;
  }
  return {};
}

QSlider* WeightsPanel::slider(Group group, int index) const {
  for (const Row& r : rows_)
    if (r.group == group && static_cast<int>(r.index) == index) return r.slider;
  return nullptr;
}

QDoubleSpinBox* WeightsPanel::spinBox(Group group, int index) const {
  for (const Row& r : rows_)
    if (r.group == group && static_cast<int>(r.index) == index) return r.spin;
  return nullptr;
}

void WeightsPanel::setWeights(const CostWeights& weights) {
  weights_ = weights;
  for (Group g : {Group::Tool, Group::Resultant, Group::Time, Group::Frequency}) {
    std::span<double> w = values(g);
    bool ok = true;
    double sum = 0.0;
    for (double v : w) {
      ok = ok && std::isfinite(v) && v >= 0.0;
      sum += v;
    }
    if (!ok || std::abs(sum - 1.0) > kWeightSumTolerance) moveWeight(w, 0, ok && sum > 0.0 ? w[0] / sum : 1.0);
  }
  committed_ = weights_;
  refresh();
}

void WeightsPanel::userSet(Group group, std::size_t index, double value, bool commit) {
  std::span<double> w = values(group);
  if (index >= w.size()) return;
  moveWeight(w, index, value);
  refresh();
  emit weightsChanged(weights_);
  if (commit) commitIfChanged();
}

void WeightsPanel::commitIfChanged() {
  if (sameWeights(weights_, committed_)) return;
  committed_ = weights_;
  emit weightsCommitted(weights_);
}

void WeightsPanel::refresh() {
  for (const Row& r : rows_) {
    const double v = values(r.group)[r.index];
    const QSignalBlocker blockSlider(r.slider);
    const QSignalBlocker blockSpin(r.spin);
    if (!r.slider->isSliderDown()) r.slider->setValue(static_cast<int>(std::lround(v * kSliderSteps)));
    r.spin->setValue(v);
  }
  ternary_->setWeights(weights_.c);
}

}  // namespace mx::widgets
