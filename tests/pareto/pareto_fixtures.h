#pragma once
// The Pareto case study (projects/rubio-pareto-case.mxproj) as engine inputs, on a coarser grid
// (100 rpm) to keep the tests fast.
#include "expert/admissible_grid.h"
#include "pareto/empirical_models.h"
#include "pareto/objective_table.h"
#include "support/fixtures.h"

namespace mx::test {

inline ExpertSettings paretoCaseSettings(double speed_step_rpm = 100.0) {
  ExpertSettings s;
  s.grid.speed_from_rev_per_s = 1000.0 / 60.0;
  s.grid.speed_to_rev_per_s = 5000.0 / 60.0;
  s.grid.speed_step_rev_per_s = speed_step_rpm / 60.0;
  s.grid.depth_divisions = 10;
  s.grid.feed_step_m = 0.01e-3;
  s.limits.spindle_power_w = 2745.3;
  s.limits.max_feed_velocity_m_per_s = 25e-3;
  s.limits.max_feed_per_tooth_m = 0.3e-3;
  s.stability.delta_per_s = 0.05;
  s.stability.alpha = 0.95;
  return s;
}

inline const AdmissibleGrid& paretoCaseGrid() {
  static const AdmissibleGrid grid(rubioR1(), paretoCaseSettings());
  return grid;
}

// The case study's objective table with the default models, built once per test binary.
inline const ObjectiveTable& paretoCaseTable() {
  static const ObjectiveTable table(paretoCaseGrid(), ParetoModels{});
  return table;
}

}  // namespace mx::test
