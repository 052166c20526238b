#pragma once
// Rule 11 requirement bounds and Rule 12 automatic weights of the Pareto expert system (Rubio et al.).
// A requirement is one objective (TOL, MRR, SURF or ROS) kept inside [lo, hi]; Rule 11 changes only
// that objective's weight (Rule 13.2) to meet it, Rule 12 runs the projected gradient ascent of the
// weights. The panel only edits and shows: the main window runs the selection.
//
// Signals: requirementChanged() once per finished user edit (enable box toggled, objective chosen,
// spin box edited: keyboard tracking is off). The bounds stay ordered: a lower bound typed above the
// upper one moves the upper one to it, and the other way round. setRequirement() emits nothing.
#include <QPointer>
#include <QString>
#include <QWidget>
#include <array>
#include <optional>

#include "display_units.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace mx::widgets {

struct RequirementView {
  int objective = 1;          // 0 TOL [min], 1 MRR [cm³/s], 2 SURF [µm], 3 ROS [–]
  double lo = 0.0, hi = 0.0;  // in those units (the panel shows MRR in the shop unit)
  bool operator==(const RequirementView&) const = default;
};

class RequirementsPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kObjectiveCount = 4;
  static constexpr int kDefaultObjective = 1;  // MRR

  explicit RequirementsPanel(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);                  // MRR shown and typed in the shop unit; nullptr: metric
  std::optional<RequirementView> requirement() const;  // nullopt when the "Require" checkbox is off
  // No signal. An objective outside [0, 3] is clamped; the bounds are clamped to the objective's range
  // and ordered. nullopt unchecks the box and keeps the last bounds.
  void setRequirement(const std::optional<RequirementView>& r);

  // Result of the last selection, as a coloured status line: "met" (green), "not reachable by the
  // weights alone" (red), and whether Rule 11 changed the weights.
  void setStatus(bool satisfied, bool weights_changed);
  void clearStatus();
  void setAutoWeightsResult(int iterations, bool converged);  // status text for Rule 12

  // Unit of an objective in RequirementView ("min", "cm³/s", "µm", "–"), the spin box suffix
  // without shop units (empty for ROS) and the objective's name ("Tool life TOL"); empty strings
  // outside [0, 3].
  static QString unit(int objective);
  static QString suffix(int objective);
  static QString objectiveName(int objective);

  QCheckBox* enableBox() const { return enable_; }
  QComboBox* objectiveCombo() const { return objective_; }
  QDoubleSpinBox* loSpin() const { return lo_; }
  QDoubleSpinBox* hiSpin() const { return hi_; }
  QPushButton* autoWeightsButton() const { return auto_; }
  QLabel* statusLabel() const { return status_; }

 signals:
  void requirementChanged();    // user changed enable/objective/lo/hi (after editing finished)
  void autoWeightsRequested();  // "Automatic weights (Rule 12)" button

 private:
  void applyObjective(int objective);  // ranges, decimals, suffixes, labels; no signal
  void refreshUnits();
  void storeShownBounds();  // the spin boxes into bounds_ of the shown objective
  double toShown(int objective, double value) const;
  double fromShown(int objective, const QDoubleSpinBox* spin, double stored) const;
  QString shownUnit(int objective) const;
  void onBoundEdited(bool lower);
  void showStatus(const QString& text, const QString& style);
  void updateEnabled();

  QCheckBox* enable_;
  QComboBox* objective_;
  QDoubleSpinBox* lo_;
  QDoubleSpinBox* hi_;
  QLabel* lo_label_;
  QLabel* hi_label_;
  QPushButton* auto_;
  QLabel* status_;
  QPointer<DisplayUnits> units_;
  ShopUnits shown_units_;  // the units the MRR bounds are shown in (DisplayUnits' after refreshUnits())
  // The bounds last shown for each objective (RequirementView units), restored when the user switches
  // back to it.
  std::array<std::array<double, 2>, kObjectiveCount> bounds_{};
  int shown_objective_ = -1;  // the objective whose bounds the spin boxes show; -1 before the first
};

}  // namespace mx::widgets
