#pragma once
// The Pareto weights w = (w_TOL, w_MRR, w_SURF, w_ROS) of the four-objective cost (Rule 10)
// as four sliders with spin boxes. The weights stay on the simplex: moving one to x rescales the
// others proportionally to their current values so that they sum to 1 - x (equal shares when they
// are all 0), the rule of WeightsPanel::moveWeight.
//
// Signals: weightsChanged() on every user change (live while a slider is dragged); weightsCommitted()
// when the change is finished (slider released, spin box edited, slider moved by keyboard or wheel)
// and the weights differ from the last commit or setWeights(). setWeights() emits nothing.
#include <QWidget>
#include <array>
#include <cstddef>

class QDoubleSpinBox;
class QSlider;

namespace mx::widgets {

class ParetoWeightsPanel : public QWidget {
  Q_OBJECT
 public:
  using Weights = std::array<double, 4>;     // TOL, MRR, SURF, ROS
  static constexpr int kSliderSteps = 1000;  // slider resolution: 0.001

  explicit ParetoWeightsPanel(QWidget* parent = nullptr);

  // No signal. Invalid weights (negative, non-finite, not summing to 1) are projected on the simplex.
  void setWeights(const Weights& weights);
  Weights weights() const { return weights_; }

  // The keep-on-simplex rule applied to `weights` (clamps value to [0, 1]).
  static void moveWeight(Weights& weights, std::size_t index, double value);

  // The controls (tests, focus); nullptr when index is out of [0, 3].
  QSlider* slider(int index) const;
  QDoubleSpinBox* spinBox(int index) const;

 signals:
  void weightsChanged(const std::array<double, 4>& weights);
  void weightsCommitted(const std::array<double, 4>& weights);

 private:
  void userSet(std::size_t index, double value, bool commit);
  void commitIfChanged();
  void refresh();

  Weights weights_{0.25, 0.25, 0.25, 0.25};
  Weights committed_{0.25, 0.25, 0.25, 0.25};
  std::array<QSlider*, 4> sliders_{};
  std::array<QDoubleSpinBox*, 4> spins_{};
};

}  // namespace mx::widgets
