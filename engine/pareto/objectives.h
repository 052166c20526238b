#pragma once
// The four objectives of the Pareto cost function (Rubio et al., Pareto paper, module V, eq. 9-15):
// tool life TOL (Taylor, eq. 10), material removal rate MRR (eq. 11), surface roughness SURF (eq. 12)
// and robustness ROS (eq. 13). TOL, MRR and ROS are maximised, SURF is minimised; after Rule 9 every
// normalised score n_i in [0, 1] is "higher is better" (SURF reversed).
#include <array>
#include <cstddef>

namespace mx {

enum class Objective : std::size_t { ToolLife = 0, Mrr = 1, Roughness = 2, Robustness = 3 };
inline constexpr std::size_t kObjectiveCount = 4;
using ObjectiveVector = std::array<double, kObjectiveCount>;

inline constexpr std::size_t index(Objective o) {
  return static_cast<std::size_t>(o);
}
// SURF is the one objective where lower is better.
inline constexpr bool isMinimised(Objective o) {
  return o == Objective::Roughness;
}
inline constexpr bool isMinimised(std::size_t i) {
  return i == index(Objective::Roughness);
}

// One point of Q with its raw objective values: tol in the Taylor model's unit (min), mrr in m^3/s,
// surf in the roughness model's unit (um), ros non-dimensional (StabilityBoundary::robustness).
struct ParetoPoint {
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  double feed_per_tooth_m = 0.0;
  double power_w = 0.0;  // peak cutting power (Pareto eq. 8)
  ObjectiveVector objectives{};
  double tol() const { return objectives[index(Objective::ToolLife)]; }
  double mrr() const { return objectives[index(Objective::Mrr)]; }
  double surf() const { return objectives[index(Objective::Roughness)]; }
  double ros() const { return objectives[index(Objective::Robustness)]; }
};

}  // namespace mx
