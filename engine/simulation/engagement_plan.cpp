#include "simulation/engagement_plan.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "model/cutting_force.h"

namespace mx {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

double reduceAngle(double phi) {
  return phi - kTwoPi * std::floor(phi / kTwoPi);
}
}  // namespace

EngagementPlanner::EngagementPlanner(const MillingSetup& setup) : EngagementPlanner(setup, straightTeeth(setup)) {}

EngagementPlanner::EngagementPlanner(const MillingSetup& setup, std::vector<CutterEdge> edges)
    : setup_(setup), edges_(std::move(edges)) {}

void EngagementPlanner::eventAngles(double theta_a, double theta_b) {
  // Edge e switches where theta + angle_e = boundary + 2 pi q, boundary in {phi_st, phi_ex}.
  angles_.clear();
  for (const CutterEdge& edge : edges_) {
    for (double boundary : {setup_.immersion.entry_rad, setup_.immersion.exit_rad}) {
      const double base = boundary - edge.angle_rad;
      for (double q = std::floor((theta_a - base) / kTwoPi); base + q * kTwoPi < theta_b; q += 1.0) {
        const double angle = base + q * kTwoPi;
        if (angle > theta_a) angles_.push_back(angle);
      }
    }
  }
  std::sort(angles_.begin(), angles_.end());
}

void EngagementPlanner::addSubStep(double begin, double end, double theta_mid, const std::array<double, 3>& stage_theta,
                                   std::vector<SubStep>& steps, std::vector<ActiveTooth>& pool) {
  SubStep sub;
  sub.begin = begin;
  sub.length = end - begin;
  const Immersion& immersion = setup_.immersion;
  for (int point = 0; point < 3; ++point) {
    sub.offsets[static_cast<std::size_t>(point)] = static_cast<std::uint32_t>(pool.size());
    for (const CutterEdge& edge : edges_) {
      // Engaged on this sub-step iff inside the immersion at its midpoint (no boundary crossed inside).
      const double mid = reduceAngle(theta_mid + edge.angle_rad);
      if (!immersion.contains(mid)) continue;
      // The stage angle measured from the midpoint, clamped against roundoff at the event instants.
      const double phi = std::clamp(mid + (stage_theta[static_cast<std::size_t>(point)] - theta_mid),
                                    immersion.entry_rad, immersion.exit_rad);
      const ToothForce unit = chipForcePerArea(setup_, phi);
      const ToothForce edge_unit = edgeForcePerDepth(setup_, phi);
      pool.push_back({std::sin(phi), std::cos(phi), unit.fx_n, unit.fy_n, edge_unit.fx_n, edge_unit.fy_n,
                      edge.depth_fraction, static_cast<std::size_t>(edge.pass_set)});
    }
  }
  sub.offsets[3] = static_cast<std::uint32_t>(pool.size());
  steps.push_back(sub);
}

EngagementTable::EngagementTable(const MillingSetup& setup, int steps_per_tooth_period)
    : EngagementTable(setup, straightTeeth(setup), steps_per_tooth_period, 1) {}

EngagementTable::EngagementTable(const MillingSetup& setup, std::vector<CutterEdge> edges, int steps_per_tooth_period,
                                 int period_teeth)
    : steps_(steps_per_tooth_period * period_teeth) {
  EngagementPlanner planner(setup, std::move(edges));
  const double step_angle = setup.toothPitchRad() / steps_per_tooth_period;
  first_.push_back(0);
  for (int s = 0; s < steps_; ++s) {
    const double theta_a = s * step_angle;
    planner.plan([&](double f) { return theta_a + f * step_angle; },
                 [&](double angle) { return (angle - theta_a) / step_angle; }, sub_steps_, pool_);
    first_.push_back(sub_steps_.size());
  }
}

}  // namespace mx
