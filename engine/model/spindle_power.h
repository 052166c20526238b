#pragma once
// The power a spindle can deliver at a speed. Below its base speed a spindle is torque-limited, so
//   P_av(N) = min(P_max, 2 pi N T_max, P_curve(N)),
// where P_curve interpolates the rows of the machine's power curve linearly, follows the first row's
// constant torque (power proportional to N from 0) below it and keeps the last row's power above it.
// Rubio et al. Pareto paper, Table 4's P column = 0.3·π·N W (N in rpm), a 9 N·m torque:
// 2 pi (N / 60) 9 = 0.3 pi N. SI: rev/s, W, N·m.
#include <cmath>
#include <limits>
#include <vector>

namespace mx {

struct SpindlePowerPoint {
  double speed_rev_per_s = 0.0;
  double power_w = 0.0;
};

struct SpindlePowerCurve {
  double max_power_w = std::numeric_limits<double>::infinity();    // P_max; +inf: no limit
  double max_torque_nm = std::numeric_limits<double>::infinity();  // T_max; +inf: no limit
  std::vector<SpindlePowerPoint> curve;                            // empty, or >= 2 rows by increasing speed

  // Throws InvalidInput naming the field, its value and its range.
  void validate() const;
  // P_av at speed_rev_per_s >= 0; +inf when nothing limits the power.
  double available(double speed_rev_per_s) const;
  // True when only P_max limits the power (the same at every speed).
  bool constant() const { return !std::isfinite(max_torque_nm) && curve.empty(); }
};

}  // namespace mx
