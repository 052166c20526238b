#pragma once
// Geometry queries on a (margined) stability boundary b_lim(N): stability verdict, the spindle
// speed security change Delta N_s (Rubio et al. 2006, section 3.B, as read in
// shared/notes/seed-reading.md) and the robustness ROS (Pareto paper, eq. 13). SI: rev/s, m.
#include <vector>

#include "stability/lobe_diagram.h"

namespace mx {

// The verdict of a depth against the lobes: stable below alpha * b_lim (Rule 1.2), unstable more than
// kMarginalBand above b_lim itself, marginal between. The band covers what a finite lobe grid, the
// interpolation and a finite simulation cannot tell apart near the border (docs/fidelity.md).
enum class StabilityVerdict { Stable, Marginal, Unstable };
inline constexpr double kMarginalBand = 0.05;
const char* verdictKey(StabilityVerdict verdict);  // "stable", "marginal", "unstable"

// Units in which a distance in the (N, b) plane is measured.
struct NormalisationSpans {
  double speed_rev_per_s = 1.0;
  double depth_m = 1.0;
};

class StabilityBoundary {
 public:
  // alpha (Rule 1.2) scales the envelope: the allowed depth is alpha * b_lim(N).
  StabilityBoundary(const LobeDiagram& diagram, double alpha = 1.0);

  double minSpeed() const { return speed_.front(); }
  double maxSpeed() const { return speed_.back(); }
  bool covers(double speed_rev_per_s) const;

  // Linear interpolation of alpha * envelope; +inf where no lobe lies below the cap. Throws
  // InvalidInput outside [minSpeed, maxSpeed].
  double depthLimit(double speed_rev_per_s) const;
  bool isStable(double speed_rev_per_s, double depth_m) const;  // b < b_lim(N)
  // Stable when isStable; marginal up to (1 + kMarginalBand) times the lobe without alpha; else unstable.
  StabilityVerdict verdict(double speed_rev_per_s, double depth_m) const;
  double alpha() const { return alpha_; }

  // Delta N_s: along depth b, per side the distance to the boundary crossing (b above that side's
  // lobe minimum) or to the speed of that side's minimum (b below it); the smaller side. Only the
  // left side counts on the highest-speed lobe. 0 on or above the boundary.
  double speedSecurity(double speed_rev_per_s, double depth_m) const;

  // Euclidean distance to the nearest point of the boundary in coordinates divided by `spans`;
  // negative (minus the distance) for an unstable point; +inf when no lobe lies below the cap.
  double scaledDistance(double speed_rev_per_s, double depth_m, const NormalisationSpans& spans) const;

  // ROS (Pareto paper, eq. 13; docs/fidelity.md, "Delta N_s and ROS"): the distance to the margined boundary with speed
  // and depth each made non-dimensional by the point's own values, i.e. the smallest relative change
  // of (N, b) that reaches the border. ROS = 1: the depth would have to double at constant speed (or
  // the speed change by 100 %). Independent of any grid or chart range, so the lobe chart, `point`,
  // the Pareto objective and the reports agree. Needs depth_m > 0.
  double robustness(double speed_rev_per_s, double depth_m) const;

  // The samples: speeds and alpha * envelope depths (+inf: no lobe below the cap).
  const std::vector<double>& speeds() const { return speed_; }
  const std::vector<double>& depths() const { return depth_; }

  // Local minima of alpha * envelope (speed, depth), ascending in speed.
  const std::vector<LobeMinimum>& minima() const { return minima_; }

 private:
  double crossingLeft(double speed, double depth, double stop) const;
  double crossingRight(double speed, double depth, double stop) const;

  std::vector<double> speed_;
  std::vector<double> depth_;
  std::vector<LobeMinimum> minima_;
  double alpha_ = 1.0;
};

}  // namespace mx
