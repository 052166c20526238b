#pragma once
// The selected Pareto point q and why it lies there: the objective (weighted J, minimum cost or
// maximum rate per part), the Rule 9 normalisation, q with its objectives, Gilbert's cost and time per
// part (when the project has pareto.economics) and the binding limits: the Rule 11 requirement when
// the selection would differ without it, the operator rules q sits on, and the limits of Q that one
// more step of depth or feed would break.
//
// Signals: objectiveChosen("weighted" | "min_cost" | "max_rate") and normalisationChosen("log" |
// "minmax" | "max") once per user choice; the setters emit nothing.
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>

#include "display_units.h"

class QComboBox;
class QLabel;

namespace mx::widgets {

struct ParetoChoiceSummary {
  double speed_rpm = 0.0, depth_mm = 0.0, feed_mm_per_tooth = 0.0;
  double mrr_cm3_s = 0.0, tol_min = 0.0, surf_um = 0.0, ros = 0.0;
  std::optional<double> cost_per_part;  // with pareto.economics
  std::optional<double> time_per_part_min;
  QStringList binding;  // one line each, for the operator
};

class ParetoChoiceSummaryPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ParetoChoiceSummaryPanel(QWidget* parent = nullptr);

  void setObjective(const QString& key);
  void setNormalisation(const QString& key);
  // min_cost and max_rate need pareto.economics: without it they are disabled in the combo box.
  void setEconomicsAvailable(bool available);
  void setSummary(const std::optional<ParetoChoiceSummary>& summary);
  void setUnits(DisplayUnits* units);  // depth, feed per tooth and MRR in shop units; nullptr: metric

  QComboBox* objectiveCombo() const { return objective_; }
  QComboBox* normalisationCombo() const { return normalisation_; }
  QLabel* pointLabel() const { return point_; }
  QLabel* bindingLabel() const { return binding_; }

 signals:
  void objectiveChosen(const QString& key);
  void normalisationChosen(const QString& key);

 private:
  QComboBox* objective_;
  QComboBox* normalisation_;
  QLabel* point_;
  QLabel* binding_;
  QPointer<DisplayUnits> units_;
  std::optional<ParetoChoiceSummary> summary_;
};

}  // namespace mx::widgets
