#pragma once
// Which teeth cut during one integration step, with their per-unit force directions from mx::toothForce
// (b = 1 m, h = 1 m): F_t = K_t b h, F_x = b (h fx_unit + ex_unit), F_y = b (h fy_unit + ey_unit)
// (2006, eq. 2-3, with the edge forces of Altintas 2000, eq. 2.22). A "tooth"
// here is a CutterEdge: a straight tooth, or one axial slice of a helical one (its share of b).
//
// A tooth entering or leaving the immersion switches the force discontinuously (partial immersion has
// h = s_t sin(phi_st) > 0 at entry), which would cut RK4 down to first order. So every step is split at
// these events into sub-steps; within a sub-step the engaged set is fixed (decided at its midpoint,
// away from any boundary) and the stage points get one-sided values at the event instants.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "model/milling_setup.h"
#include "simulation/cutter_edges.h"

namespace mx {

struct ActiveTooth {
  double sin_phi = 0.0;
  double cos_phi = 0.0;
  double fx_unit = 0.0;  // [N / m^2]: F_x per unit b h
  double fy_unit = 0.0;
  double ex_unit = 0.0;  // [N / m]: the edge force's F_x per unit b
  double ey_unit = 0.0;
  double depth_fraction = 1.0;  // the edge's share of b
  std::size_t pass_set = 0;     // its tooth's passes (ToothPasses)
};

// One RK4 sub-step [begin, begin + length] (fractions of dt); its three stage points are begin,
// begin + length/2 and begin + length, whose engaged teeth are pool[offsets[p] .. offsets[p + 1]).
struct SubStep {
  double begin = 0.0;
  double length = 1.0;
  std::array<std::uint32_t, 4> offsets{};
};

struct StepPlanView {
  std::span<const SubStep> sub_steps;
  const ActiveTooth* pool = nullptr;
  std::span<const ActiveTooth> teeth(const SubStep& s, int point) const {
    const auto p = static_cast<std::size_t>(point);
    return {pool + s.offsets[p], static_cast<std::size_t>(s.offsets[p + 1] - s.offsets[p])};
  }
};

// Builds the plan of a step over which the cutter angle rises monotonically from theta(0) to theta(1).
class EngagementPlanner {
 public:
  explicit EngagementPlanner(const MillingSetup& setup);  // the straight teeth
  EngagementPlanner(const MillingSetup& setup, std::vector<CutterEdge> edges);

  // theta(f): cutter angle at fraction f of the step; fraction(angle): its inverse on [0, 1].
  // Appends the sub-steps to `steps` and their teeth to `pool` (offsets index into pool).
  template <class Theta, class Fraction>
  void plan(Theta theta, Fraction fraction, std::vector<SubStep>& steps, std::vector<ActiveTooth>& pool);

 private:
  void eventAngles(double theta_a, double theta_b);  // fills angles_ with the switching angles in (a, b)
  void addSubStep(double begin, double end, double theta_mid, const std::array<double, 3>& stage_theta,
                  std::vector<SubStep>& steps, std::vector<ActiveTooth>& pool);

  const MillingSetup& setup_;
  std::vector<CutterEdge> edges_;
  std::vector<double> angles_;
  std::vector<double> cuts_;
};

// Constant speed: the plan of step s repeats every `period_teeth` mean tooth periods (m steps each: one
// for uniform teeth sharing their passes, n_t otherwise), so it is tabulated once. Step s covers theta
// from s dtheta to (s + 1) dtheta with dtheta = (2 pi / n_t) / m.
class EngagementTable {
 public:
  EngagementTable(const MillingSetup& setup, int steps_per_tooth_period);  // straight teeth, one tooth period
  EngagementTable(const MillingSetup& setup, std::vector<CutterEdge> edges, int steps_per_tooth_period,
                  int period_teeth);
  int steps() const { return steps_; }
  StepPlanView step(std::int64_t n) const {
    const auto s = static_cast<std::size_t>(n % steps_);
    return {{sub_steps_.data() + first_[s], first_[s + 1] - first_[s]}, pool_.data()};
  }

 private:
  int steps_;
  std::vector<std::size_t> first_;  // sub_steps_[first_[s] .. first_[s + 1]) belong to step s
  std::vector<SubStep> sub_steps_;
  std::vector<ActiveTooth> pool_;
};

// --- implementation of the template -------------------------------------------------------------

template <class Theta, class Fraction>
void EngagementPlanner::plan(Theta theta, Fraction fraction, std::vector<SubStep>& steps,
                             std::vector<ActiveTooth>& pool) {
  constexpr double kMinFraction = 1e-7;  // events closer than this to a step end or each other merge
  eventAngles(theta(0.0), theta(1.0));
  cuts_.clear();
  cuts_.push_back(0.0);
  for (double angle : angles_) {
    const double f = fraction(angle);
    if (f > cuts_.back() + kMinFraction && f < 1.0 - kMinFraction) cuts_.push_back(f);
  }
  cuts_.push_back(1.0);
  for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
    const double a = cuts_[i], b = cuts_[i + 1];
    addSubStep(a, b, theta(0.5 * (a + b)), {theta(a), theta(0.5 * (a + b)), theta(b)}, steps, pool);
  }
}

}  // namespace mx
