#pragma once
// The cost weights of the 2006 expert system, for engineers: c = (c1 power, c2 MRR, c3 Delta N_s)
// of the tool cost C (eq. 13) as three sliders with spin boxes and a ternary picker; c_r = (C, C_t,
// C_f) of C_resultant (eq. 20); c_t = (t_s, M_p) of C_t (eq. 18) and c_f = (R12h, R1ch) of C_f
// (eq. 19). Every group stays on its simplex: moving one weight to x rescales the others of its
// group proportionally to their current values so that they sum to 1 - x (equal shares when they
// are all 0; for a pair the other one is 1 - x).
//
// Signals: weightsChanged() on every user change (live while a slider or the ternary marker is
// dragged); weightsCommitted() when the change is finished (slider or ternary released, a spin box
// edited, a slider moved by keyboard or wheel), only when the weights differ from the last commit
// or setWeights(); resetRequested() from the "Reset to project" button. setWeights() emits nothing.
#include <QWidget>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "expert/cost_weights.h"

class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QPushButton;
class QSlider;

namespace mx::widgets {

class TernaryPicker;

class WeightsPanel : public QWidget {
  Q_OBJECT
 public:
  enum class Group { Tool, Resultant, Time, Frequency };  // c, c_r, c_t, c_f
  static constexpr int kSliderSteps = 1000;               // slider resolution: 0.001

  explicit WeightsPanel(QWidget* parent = nullptr);

  void setWeights(const mx::CostWeights& weights);  // no signal
  mx::CostWeights weights() const { return weights_; }

  // The keep-on-simplex rule: sets weights[index] = clamp(value, 0, 1) and rescales the others (see
  // the file comment). Afterwards all are >= 0 and sum to 1 within a few ulp.
  static void moveWeight(std::span<double> weights, std::size_t index, double value);

  // The controls (tests, focus handling). index: 0-based within the group; nullptr when out of range.
  QSlider* slider(Group group, int index) const;
  QDoubleSpinBox* spinBox(Group group, int index) const;
  TernaryPicker* ternaryPicker() const { return ternary_; }
  QPushButton* resetButton() const { return reset_; }

 signals:
  void weightsChanged(const mx::CostWeights& weights);
  void weightsCommitted(const mx::CostWeights& weights);
  void resetRequested();

 private:
  struct Row {
    Group group;
    std::size_t index;
    QSlider* slider;
    QDoubleSpinBox* spin;
  };
  struct RowSpec {
    const char* label;
    const char* tip;
  };

  QGroupBox* addGroup(Group group, const QString& title, const QString& tip, const std::vector<RowSpec>& rows,
                      QWidget* top = nullptr);
  std::span<double> values(Group group);
  void userSet(Group group, std::size_t index, double value, bool commit);
  void commitIfChanged();
  void refresh();

  mx::CostWeights weights_;
  mx::CostWeights committed_;
  std::vector<Row> rows_;
  TernaryPicker* ternary_ = nullptr;
  QPushButton* reset_ = nullptr;
};

}  // namespace mx::widgets
