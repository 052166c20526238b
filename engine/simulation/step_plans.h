#pragma once
// The engagement plan of integration step n (which teeth cut in each sub-step, EngagementPlanner),
// tabulated at constant speed or planned on the fly from theta(t) under spindle speed variation.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "model/milling_setup.h"
#include "simulation/engagement_plan.h"
#include "simulation/spindle_kinematics.h"

namespace mx {

// Constant speed: step n uses the tabulated plan of step n mod (m period_teeth).
class TabulatedPlans {
 public:
  TabulatedPlans(const MillingSetup& setup, std::vector<CutterEdge> edges, int steps_per_tooth, int period_teeth)
      : table_(setup, std::move(edges), steps_per_tooth, period_teeth) {}
  StepPlanView at(std::int64_t n) { return table_.step(n); }

 private:
  EngagementTable table_;
};

// Any speed law: the plan of step n from theta(t), event instants by safeguarded Newton on theta(t) = angle.
class KinematicPlans {
 public:
  KinematicPlans(const MillingSetup& setup, std::vector<CutterEdge> edges, const SpindleKinematics& kinematics,
                 double dt)
      : planner_(setup, std::move(edges)), kinematics_(kinematics), dt_(dt) {}
  StepPlanView at(std::int64_t n) {
    const double t0 = static_cast<double>(n) * dt_;
    auto theta = [&](double f) { return kinematics_.angleRad(t0 + f * dt_); };
    auto fraction = [&](double angle) {
      double lo = 0.0, hi = 1.0, f = 0.5;
      for (int i = 0; i < 60; ++i) {
        const double g = theta(f) - angle;
        if (g > 0.0)
          hi = f;
        else
          lo = f;
        double next = f - g / (2.0 * std::numbers::pi * kinematics_.speedRevPerS(t0 + f * dt_) * dt_);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - f) < 1e-15) return next;
        f = next;
      }
      return f;
    };
    steps_.clear();
    pool_.clear();
    planner_.plan(theta, fraction, steps_, pool_);
    return {steps_, pool_.data()};
  }

 private:
  EngagementPlanner planner_;
  const SpindleKinematics& kinematics_;
  double dt_;
  std::vector<SubStep> steps_;
  std::vector<ActiveTooth> pool_;
};

}  // namespace mx
